#pragma once
// The assembly sheet of a plan printed apart (docs/apart.md, "Assembly sheet"): one HTML page with pictures
// rendered in software (assembly/picture.h): the parts exploded with their numbers, the order of gluing with
// each joint's two sides and its dowels highlighted, the plates with their parts and the slicer's estimates.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "multidir/assembly/dowels.h"
#include "multidir/assembly/part_labels.h"
#include "multidir/assembly/plates.h"

namespace multidir::assembly {

// One step of gluing: `part` joins the parts glued before it at `joints` (all its joints with them; the first
// step is the first part alone).
struct GluingStep {
  int part = 0;
  std::vector<int> joints;
};

// Part 1 (the plan's first region, the one on the platform) first; then, each time, the part sharing the most
// joint area with the parts already glued (ties: the lower number), so every step glues onto something
// already rigid. A part joined to nothing comes when nothing else is left.
std::vector<GluingStep> gluingOrder(const core::ApartPlan& plan);

// What the slicer estimated for one plate, or for the model in one piece with supports.
struct SheetEstimate {
  std::string what;          // "Plate 1", "One piece with supports"
  double seconds = 0.0;
  double filamentCm3 = 0.0;
  double supportCm3 = 0.0;   // the filament the slicer spends on support material
};

struct SheetInput {
  std::string title;
  const core::ApartPlan* plan = nullptr;
  const DowelLayout* layout = nullptr;
  DowelOptions dowelOptions;
  const std::vector<PartLabel>* labels = nullptr;
  const std::vector<core::TriangleMesh>* parts = nullptr;   // as printed: drilled and numbered, model frame
  const std::vector<core::TriangleMesh>* dowels = nullptr;  // model frame
  const PlateLayout* plates = nullptr;
  std::vector<SheetEstimate> estimates;                     // per plate, then the one piece; empty: not sliced
};

struct SheetPicture {
  std::string name;  // file name, relative to the page ("sheet/step-02.png")
  std::vector<std::uint8_t> png;
};

struct Sheet {
  std::string html;
  std::vector<SheetPicture> pictures;
};

// Errors: InvalidParameter when an input is missing or the parts, labels and plan disagree in number.
core::Result<Sheet> assemblySheet(const SheetInput& input);

}  // namespace multidir::assembly
