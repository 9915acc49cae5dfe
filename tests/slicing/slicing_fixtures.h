#pragma once
// Plans made in memory for the slicing tests (decompose + supports, as `multidir decompose` makes them) and
// the coarse slicer settings that keep the tests quick.
#include <string>
#include <utility>
#include <vector>

#include "multidir/core/plan/print_job.h"
#include "multidir/slicing/slice_job.h"

namespace multidir::test {

// decompose(model scaled by `scale` about the origin, machine) with the greedy search (quick) and supports
// grown, as a LoadedPlan (nothing written). Scaling keeps the tests' slicing short and the parts on the beds.
core::LoadedPlan plannedInMemory(const core::TriangleMesh& model, const core::MachineSpec& machine,
                                 const std::string& modelName, double scale = 1.0);

// A print job in the machine frame of such a plan.
core::PrintJob machineJob(const core::LoadedPlan& plan);

// Coarse layers, sparse infill: a region slices in about a second.
std::vector<std::pair<std::string, std::string>> coarseSettings(double layerHeightMm);

// Every extrusion move of a G-code file (parsed), with its step marker.
std::vector<slicing::GcodeMove> extrusionsOf(const std::string& gcodePath);

std::string readFile(const std::string& path);

// Writes `text` to NAME.ini in a fresh scratch folder named `folder`.NAME; returns its path.
std::string writeProfileFile(const std::string& folder, const std::string& name, const std::string& text);

}  // namespace multidir::test
