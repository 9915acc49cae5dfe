#include "support/test_models.h"

#include <filesystem>
#include <stdexcept>

#include "multidir/core/mesh/mesh_io.h"

namespace multidir::test {

std::string sharedModelPath(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(MULTIDIR_SHARED_MODELS_DIR) / name;
  if (!std::filesystem::exists(path))
    throw std::runtime_error("shared test model missing: " + path.string() +
                             " (the shared/ folder must sit beside the repository)");
  return path.string();
}

const std::vector<std::string>& closedSharedModels() {
  static const std::vector<std::string> models = {"kitten.off",      "fertility.off", "bunny.off",
                                                  "3holes.off",      "cheburashka.off", "knight.off",
                                                  "fandisk.off",     "bumpy.off",     "screwdriver.off"};
  return models;
}

std::string scratchDirectory(const std::string& testName) {
  const std::filesystem::path dir = std::filesystem::path(MULTIDIR_BINARY_DIR) / "test-scratch" / testName;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

core::TriangleMesh loadSharedModel(const std::string& name) {
  auto loaded = core::loadMesh(sharedModelPath(name));
  if (!loaded.ok()) throw std::runtime_error(loaded.error().describe());
  return loaded->mesh;
}

}  // namespace multidir::test
