#include "slicing_fixtures.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "multidir/core/search/decompose.h"
#include "multidir/core/supports/projected_supports.h"
#include "multidir/slicing/gcode_program.h"
#include "support/test_models.h"

namespace multidir::test {

core::LoadedPlan plannedInMemory(const core::TriangleMesh& unscaled, const core::MachineSpec& machine,
                                 const std::string& modelName, double scale) {
  core::TriangleMesh model = unscaled;
  for (core::Vec3& v : model.vertices) v *= scale;
  core::SearchOptions options;
  options.scheme = core::SearchScheme::Greedy;
  core::JobContext job;
  core::Result<core::Decomposition> plan = core::decompose(model, machine, options, job);
  if (!plan) throw std::runtime_error("decompose " + modelName + ": " + plan.error().describe());
  core::Result<core::ProjectedSupports> supports =
      core::generateSupports(model, *plan, machine, core::SupportOptions{}, job);
  if (!supports) throw std::runtime_error("supports " + modelName + ": " + supports.error().describe());
  core::LoadedPlan loaded;
  loaded.metadata.modelPath = modelName;
  loaded.metadata.up = machine.up;
  loaded.metadata.machine = machine;
  loaded.metadata.multidirVersion = "test";
  loaded.decomposition = std::move(plan).value();
  loaded.supports = supports->regions;
  loaded.directory = modelName + "-plan";
  return loaded;
}

core::PrintJob machineJob(const core::LoadedPlan& plan) {
  core::Result<core::PrintJob> job = core::buildPrintJob(plan, core::PrintJobOptions{});
  if (!job) throw std::runtime_error("print job: " + job.error().describe());
  return std::move(job).value();
}

std::vector<std::pair<std::string, std::string>> coarseSettings(double layerHeightMm) {
  const std::string h = std::to_string(layerHeightMm);
  return {{"layer_height", h},          {"first_layer_height", h}, {"perimeters", "1"},    {"top_solid_layers", "1"},
          {"bottom_solid_layers", "1"}, {"fill_density", "0%"},    {"gcode_comments", "0"}};
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string writeProfileFile(const std::string& folder, const std::string& name, const std::string& text) {
  const std::string path = scratchDirectory(folder + "." + name) + "/" + name + ".ini";
  std::ofstream(path) << text;
  return path;
}

std::vector<slicing::GcodeMove> extrusionsOf(const std::string& gcodePath) {
  core::Result<slicing::GcodeProgram> program = slicing::parseGcode(readFile(gcodePath));
  if (!program) throw std::runtime_error(program.error().describe());
  std::vector<slicing::GcodeMove> moves;
  for (const slicing::GcodeMove& m : program->moves)
    if (m.extrudes()) moves.push_back(m);
  return moves;
}

}  // namespace multidir::test
