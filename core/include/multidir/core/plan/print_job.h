#pragma once
// Print jobs: what the printer needs from a plan. One mesh per region in printing order, placed as the machine
// holds the part while that region is printed, its supports beside it, and print-job.json with the machine
// angles and start height of every step (schema "multidir-print-job", docs/plan-format.md).
//
// Folder layout written by exportPrintJob:
//   step-01-region.stl     the region printed first (the format asked for: .stl .obj .ply .off), ...
//   step-01-supports.stl   optional: the supports printed with it, ...
//   print-job.json         written last: a folder whose print-job.json exists holds a complete job
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/plan/plan_file.h"

namespace multidir::core {

constexpr int kPrintJobFormatVersion = 1;

// The rigid motion the machine applies to the part (model coordinates, mm) so that `printingDirection`
// points along machine.up; `pivot` is the point the platform turns about (it stays where it is): the
// platformRotation (machine.h, the one pose convention) of the direction's machineAnglesFor, about the pivot.
// Precondition: `printingDirection` is non-zero and realizable by `machine` (isRealizable); only then does
// pose.linear() * direction equal up. Thread-safe (pure).
Eigen::Isometry3d machinePose(const MachineSpec& machine, const Vec3& printingDirection, const Vec3& pivot);

struct PrintJobOptions {
  // Machine: every step as the machine holds it, in the machine's frame turned so that up is +Z (what a
  // slicer expects): the platform frame (platformFrameX(up), up x that, up) becomes (+X, +Y, +Z), with the
  // platform centre at the origin, so each region's base lies flat at its lowest z. Model: as in the model.
  enum class Frame { Machine, Model };

  std::string format = "stl";  // mesh files: "stl" (binary), "obj", "ply" or "off", as saveMesh writes them
  Frame frame = Frame::Machine;
  bool supports = true;  // false: no support files, even where the plan has supports
};

// "machine", "model" (as the command line and print-job.json spell them).
const char* printJobFrameName(PrintJobOptions::Frame frame);
// Errors: InvalidParameter naming the frames there are.
Result<PrintJobOptions::Frame> parsePrintJobFrame(const std::string& text);

// Errors: UnsupportedFormat (format is not one of stl, obj, ply, off; the message lists them).
Status validate(const PrintJobOptions& options);

// One region of the plan as the printer gets it.
struct PrintJobStep {
  int index = 1;                           // printing position, from 1
  std::string regionFile;                  // "step-01-region.stl"
  std::string supportsFile;                // "step-01-supports.stl"; empty when the step prints no supports
  Vec3 printingDirection = Vec3::UnitZ();  // model frame, unit
  MachineAngles angles;                    // of printingDirection on PrintJob::machine (degrees)
  std::optional<Plane> basePlane;          // model frame; none for the first step, which stands on the platform
  // Where the nozzle starts: the region's lowest point along up once the machine has posed the part,
  // measured from the platform plane at rest through the pivot (the lowest z of the machine-frame file).
  double lowestHeightMm = 0.0;
  double volumeMm3 = 0.0;                                         // the plan's (computed on the exact mesh)
  double riskyAreaMm2 = 0.0;                                      // the plan's
  double supportVolumeMm3 = 0.0;                                  // 0 without supports
  Eigen::Isometry3d modelToFile = Eigen::Isometry3d::Identity();  // takes model coordinates to the files'
  TriangleMesh region;    // in the files' frame; face origins kept from the plan
  TriangleMesh supports;  // in the files' frame; empty when supportsFile is
};

struct PrintJob {
  PrintJobOptions options;
  MachineSpec machine;              // the plan's machine as it prints the plan (4-DOF: about the plan's rotation axis)
  PlatformRegion platform;          // of the first step's region, model frame; its centre is the pivot of every pose
  std::string modelPath;            // from the plan's metadata
  std::string modelChecksum;        // from the plan's metadata; empty when unknown
  Vec3 modelUp = Vec3::UnitZ();     // from the plan's metadata
  std::string planDirectory;        // LoadedPlan::directory
  std::vector<PrintJobStep> steps;  // in printing order
};

// The job in memory, nothing written: the plan's regions in printing order, each moved by modelToFile
// (Machine: the machinePose of its printing direction about the platform centre of region 1, then the
// machine's up turned to +Z with that centre at the origin), with the supports of `plan.supports` unless
// options.supports is false. Errors: UnsupportedFormat (see validate), InvalidParameter for an inconsistent
// plan (no regions, an invalid machine, a support list that does not match the regions, an empty region, a
// first region not printed along up, a base plane whose normal is not the printing direction, a direction the
// machine cannot print; the message names the region), TooLarge (not enough memory for the posed meshes).
Result<PrintJob> buildPrintJob(const LoadedPlan& plan, const PrintJobOptions& options);

// Writes a job from buildPrintJob into `directory` (created with its parents when missing): the step meshes
// first, each written beside its target and renamed into place, then print-job.json the same way. An older
// print-job.json there is removed before the first step file is written, so a failed export never leaves a
// job description naming files of another job; step files of an older, longer job are left alone
// (print-job.json names the files that belong to it).
// Errors: UnsupportedFormat (options.format), InvalidParameter (no steps, or a file name that is not a plain
// name with the format's extension), WriteFailed naming the folder or the file that could not be written.
Status writePrintJob(const PrintJob& job, const std::string& directory);

// buildPrintJob, then writePrintJob. Errors: those of both.
Status exportPrintJob(const LoadedPlan& plan, const PrintJobOptions& options, const std::string& directory);

}  // namespace multidir::core
