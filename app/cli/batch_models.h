#pragma once
// The models of `multidir batch`: a folder's mesh files or a list file's paths, in sorted order, and the share
// of them one shard (--shard I/N) takes.
#include <string>
#include <vector>

namespace multidir::cli {

struct Shard {
  int index = 0;  // I, from 0
  int count = 1;  // N
};

// "I/N" with 0 <= I < N; UsageError otherwise.
Shard parseShard(const std::string& text);

struct BatchModel {
  std::string path;  // as listed (a list file's relative paths resolved against its folder)
  std::string name;  // its file name: the name of its plan folder, unique in the batch
  int index = 0;     // position in the sorted list of all the batch's models
};

// INPUT as a sorted list (byte order of the paths): a folder's .stl, .obj, .off and .ply files (any case; not
// its subfolders), or a list file's lines (blank lines and lines starting with # left out). FileError when
// INPUT cannot be read, holds no model, or two models share a file name (their plan folders would clash).
std::vector<BatchModel> batchModels(const std::string& input);

// The models whose index is shard.index modulo shard.count, in order.
std::vector<BatchModel> shardOf(const std::vector<BatchModel>& models, const Shard& shard);

}  // namespace multidir::cli
