#pragma once
// A plan printed apart on an ordinary printer, the whole way (docs/apart.md): the parts cut to fit the printer,
// drilled for dowels and numbered, laid on plates, written as STL and 3MF, the plates and the model in one piece
// sliced with the slicer's supports, the assembly sheet and apart.json. The command line (`multidir apart`) and
// the studio's Print apart view both call printApart; neither repeats a step of it.
#include <optional>
#include <string>
#include <vector>

#include "multidir/assembly/dowels.h"
#include "multidir/assembly/part_labels.h"
#include "multidir/assembly/plates.h"
#include "multidir/core/apart/apart_plan.h"
#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/slicing/estimates.h"
#include "multidir/slicing/printer_profile.h"

namespace multidir::apart {

struct PrintApartOptions {
  // The printer: its bed and height limit the parts and make the plates, its settings slice them. None: parts
  // are not limited in size, one plate holds them all, nothing is sliced.
  std::optional<slicing::PrinterProfile> printer;
  bool slice = true;  // with a printer: slice every plate and the one piece
  int maxParts = 64;  // core::ApartOptions::maxParts
  // The overhang angle the plan was searched with: the slicer's support threshold for the plates and the one
  // piece, and the risky area's definition for J_G apart.
  double alphaMaxDegrees = core::kDefaultAlphaMaxDegrees;
  assembly::DowelOptions dowels;
  assembly::LabelOptions labels;
  std::string title = "Assembly";  // the assembly sheet's heading
};

// What the slicer estimated for one plate (supports on where the plate's parts need them).
struct PlateEstimate {
  int plate = 0;  // 0-based
  slicing::Estimate estimate;
};

struct ApartResult {
  core::ApartPlan plan;                        // parts (undrilled, model frame), joints, J_G apart
  assembly::DowelLayout layout;                // the dowels, per joint
  std::vector<assembly::PartLabel> labels;     // per part: its number and where it is sunk, or why not
  std::vector<core::TriangleMesh> parts;       // as printed: drilled and numbered, model frame
  std::vector<core::TriangleMesh> dowels;      // model frame
  assembly::PlateLayout plates;                // every part and dowel laid on its plate
  assembly::PlateOptions plateOptions;         // the bed the plates were laid on
  double jgPlanMm2 = 0.0;                      // the plan's J_G on its own machine
  double jgBeforeMm2 = 0.0;                    // the model in one piece along up
  bool sliced = false;                         // the estimates below are the slicer's
  std::vector<PlateEstimate> plateEstimates;   // one per plate
  slicing::Estimate total;                     // all plates
  slicing::Estimate whole;                     // the model in one piece with the slicer's supports
  std::string folder;                          // where the files are (absolute)
  std::vector<std::string> files;              // written, relative to `folder`, in the order written
};

// Runs the pipeline on `plan` and writes every file into `folder` (created when missing). The files are written
// into a staged folder beside it that takes its place only when everything is done: a folder that is missing,
// empty or holds an earlier apart.json is replaced as a whole; a folder holding other files gets the new files
// moved in, apart.json last, and keeps the others. Progress in `job` by stage ("plan", "dowels", "drilling",
// "numbers", "plates", "3MF", "slicing plate i of n", "slicing the one piece", "assembly sheet"); a cancel is
// seen between stages, between plates and inside the slicer, and leaves `folder` as it was.
// Errors: what the failing stage says (core::apartPlan's TooLarge for a part that cannot be cut to fit,
// drilling's Internal, the slicer's ExternalToolFailed), Cancelled, WriteFailed.
core::Result<ApartResult> printApart(const core::Decomposition& plan, const PrintApartOptions& options,
                                     const std::string& folder, core::JobContext& job);

// Copies the files of `result` into `folder` the way printApart writes them (staged, then put in place): the
// studio's Export. Errors: WriteFailed naming the file or folder.
core::Status copyApartFiles(const ApartResult& result, const std::string& folder);

// PrusaSlicer's `support_material_threshold` for a plan's alpha_max (degrees): the slicer then supports the
// faces whose normal is less than floor(alpha_max) degrees from straight down, never a face J_G counts as
// self-supporting (docs/apart.md, "Where the slicer puts support"). At least 1: 0 is the slicer's own rule.
int slicerSupportThreshold(double alphaMaxDegrees);

// Where the plates are laid and what the parts must fit, for a printer (or none).
assembly::PlateOptions plateOptionsFor(const std::optional<slicing::PrinterProfile>& printer);

}  // namespace multidir::apart
