#pragma once
// One small interface to a slicer engine, so another one (CuraEngine) can be added beside PrusaSlicer.
// An engine turns mesh files into one G-code file with the settings of one or more config files.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"

namespace multidir::slicing {

struct SliceRequest {
  std::string meshFile;                  // one solid (an STL may hold overlapping shells: they are united)
  std::vector<std::string> configFiles;  // applied in order, later files overriding earlier ones
  // The engine drops the mesh to z = 0 and adds this to every Z it writes, so layers start at this height.
  // XY stays where the mesh is (no arranging or centring).
  double zOffsetMm = 0.0;
  std::string outputFile;  // the G-code, written by the engine
  // Called (on the slicing thread) with the fraction of the run done so far, in [0, 1], as the engine says it.
  std::function<void(double fraction)> progress;
  double heightMm = 0.0;  // the mesh's height, for progress while the G-code is written (0: unknown)
};

struct SliceRun {
  std::string gcode;    // the output file's text
  std::string command;  // as run, for messages and logs
  double seconds = 0.0; // wall time of the engine
};

class SlicerEngine {
 public:
  virtual ~SlicerEngine() = default;
  virtual std::string name() const = 0;
  // Errors: FileNotFound (the engine is not installed; the message names the command), ExternalToolFailed
  // (it failed or wrote no G-code; the message names the command and its last output lines), Cancelled.
  // Thread-safe: each call runs its own process.
  virtual core::Result<SliceRun> slice(const SliceRequest& request, core::JobContext& context) const = 0;
};

// PrusaSlicer (2.5 and later) run headless: prusa-slicer --loglevel 1 --export-gcode --load ... --dont-arrange
// --z-offset H -o OUT MESH. Progress: its own status lines ("70 => Infilling layers", percent of its stages)
// while it slices, then while it writes the G-code (its last and often longest stage, from 90 %) the height the
// G-code it is writing has reached, over the mesh's height.
class PrusaSlicerEngine : public SlicerEngine {
 public:
  explicit PrusaSlicerEngine(std::string executable = "prusa-slicer");
  std::string name() const override { return "PrusaSlicer"; }
  core::Result<SliceRun> slice(const SliceRequest& request, core::JobContext& context) const override;

 private:
  std::string m_executable;
};

}  // namespace multidir::slicing
