#pragma once
// The G-code preview's geometry, without VTK: every move of every step's program as a line segment in the
// plan's model coordinates (each step's machine pose undone, so the toolpaths lie where the plan view shows
// the regions), with the layer it belongs to, numbered over the whole job in printing order.
//
// Which moves: those after a step's "; MULTIDIR STEP k" marker (the start sequence's purge and the end
// sequence's lift and park are the printer's, not the part's). Extrusions push filament while moving in XY;
// travel is every other move that goes somewhere (XY or Z), retractions in place are neither.
// Layers: a step's layer count rises each time an extrusion lies higher (printer z) than the step's layer so
// far; a travel belongs to the layer in progress. Travels before a step's first extrusion are left out: they
// come from where the previous step parked, a place that means nothing in the step's own pose.
//
// Thread: pure functions on values; the slicing runner builds a preview on its worker thread.
#include <Eigen/Geometry>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/slicing/gcode_program.h"

namespace multidir::ui {

struct ToolpathSegment {
  core::Vec3 from = core::Vec3::Zero();  // model coordinates, mm
  core::Vec3 to = core::Vec3::Zero();
  int step = 1;   // the step (from 1): its colour is regionColor(step - 1)
  int layer = 1;  // over the whole job, from 1
  int line = 0;   // the move's line in its step's program (step-NN.gcode), from 1
  // The audit's check (b) found this extrusion resting on nothing printed before it (markUnsupported).
  bool unsupported = false;
};

// One layer of the job: which step prints it, and its number within that step (both from 1).
struct ToolpathLayer {
  int step = 1;
  int layerInStep = 1;
  double printerZMm = 0.0;
};

struct GcodePreview {
  // Each in printing order, so the segments of layers 1..N are a prefix (layers never decrease along them).
  std::vector<ToolpathSegment> extrusions;
  std::vector<ToolpathSegment> travels;
  std::vector<ToolpathLayer> layers;  // layers[i] is layer i + 1
  int stepCount = 0;
  // The audit's check (b) (docs/slicing.md "Audit"), when it ran on the job: the unsupported extrusions are
  // marked and these are its totals over the step programs.
  bool audited = false;
  double auditedExtrusionMm = 0.0;
  double unsupportedMm = 0.0;

  [[nodiscard]] int layerCount() const { return static_cast<int>(layers.size()); }
  // How many extrusions (travels) belong to layers 1..`layers` (clamped to the job's).
  [[nodiscard]] std::size_t extrusionsUpTo(int layers) const;
  [[nodiscard]] std::size_t travelsUpTo(int layers) const;
};

// One step's program as the printer runs it.
struct StepProgram {
  int step = 1;
  slicing::GcodeProgram program;
  Eigen::Isometry3d modelToPrinter = Eigen::Isometry3d::Identity();  // slicing::SlicedStep::modelToPrinter
};

// The preview of `steps` (in printing order).
GcodePreview buildGcodePreview(const std::vector<StepProgram>& steps);

// Marks the extrusions of step `step` whose line is in `lines` (ascending, as the audit lists them); returns
// how many were marked.
std::size_t markUnsupported(GcodePreview& preview, int step, const std::vector<int>& lines);

}  // namespace multidir::ui
