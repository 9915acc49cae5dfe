#include "batch_models.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>

#include "cli_args.h"

namespace multidir::cli {
namespace {

namespace fs = std::filesystem;

const std::string kCommand = "multidir batch";

bool isMeshFile(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".stl" || extension == ".obj" || extension == ".off" || extension == ".ply";
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

std::vector<std::string> folderModels(const fs::path& folder) {
  std::vector<std::string> paths;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && isMeshFile(it->path())) paths.push_back(it->path().string());
  if (ec) throw FileError(kCommand + ": cannot list the folder " + folder.string() + ": " + ec.message());
  return paths;
}

std::vector<std::string> listedModels(const fs::path& listFile) {
  std::ifstream in(listFile);
  if (!in) throw FileError(kCommand + ": cannot read the list file " + listFile.string());
  std::vector<std::string> paths;
  for (std::string line; std::getline(in, line);) {
    const std::string path = trimmed(line);
    if (path.empty() || path[0] == '#') continue;
    paths.push_back(fs::path(path).is_absolute() ? path : (listFile.parent_path() / path).string());
  }
  return paths;
}

}  // namespace

Shard parseShard(const std::string& text) {
  const auto slash = text.find('/');
  auto whole = [&](const std::string& part) {
    if (part.empty() || part.size() > 9 || !std::all_of(part.begin(), part.end(), [](unsigned char c) { return std::isdigit(c); }))
      throw UsageError(kCommand + ": --shard expects I/N, two whole numbers with 0 <= I < N (such as 0/4), got '" +
                       text + "'");
    return std::stoi(part);
  };
  if (slash == std::string::npos) whole("");
  Shard shard;
  shard.index = whole(text.substr(0, slash));
  shard.count = whole(text.substr(slash + 1));
  if (shard.count < 1 || shard.index >= shard.count)
    throw UsageError(kCommand + ": --shard " + text + ": I must be at least 0 and less than N");
  return shard;
}

std::vector<BatchModel> batchModels(const std::string& input) {
  std::error_code ec;
  const fs::path path(input);
  if (!fs::exists(path, ec)) throw FileError(kCommand + ": " + input + " does not exist: give a folder of meshes or a list file");
  std::vector<std::string> paths = fs::is_directory(path, ec) ? folderModels(path) : listedModels(path);
  if (paths.empty())
    throw FileError(kCommand + ": " + input + " holds no model (.stl, .obj, .off or .ply files, or one path per line)");
  std::sort(paths.begin(), paths.end());
  std::vector<BatchModel> models;
  std::map<std::string, std::string> byName;
  for (const std::string& p : paths) {
    BatchModel model{p, fs::path(p).filename().string(), static_cast<int>(models.size())};
    const auto [it, inserted] = byName.emplace(model.name, p);
    if (!inserted)
      throw FileError(kCommand + ": " + it->second + " and " + p + " have the same file name, so their plan folders " +
                      "would be one; rename one of them");
    models.push_back(std::move(model));
  }
  return models;
}

std::vector<BatchModel> shardOf(const std::vector<BatchModel>& models, const Shard& shard) {
  std::vector<BatchModel> share;
  for (const BatchModel& model : models)
    if (model.index % shard.count == shard.index) share.push_back(model);
  return share;
}

}  // namespace multidir::cli
