#pragma once
// Where a bench program finds a model: a name of ../shared/models (without .off) or a path (anything with a /).
#include <string>

namespace multidir::bench {

inline std::string sharedModelPath(const std::string& nameOrPath) {
  if (nameOrPath.find('/') != std::string::npos) return nameOrPath;
  return std::string(MULTIDIR_SHARED_MODELS_DIR) + "/" + nameOrPath + ".off";
}

}  // namespace multidir::bench
