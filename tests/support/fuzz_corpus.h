#pragma once
// The committed corpora of the libFuzzer harnesses (tests/fuzz/corpus-NAME/), for the tests that replay them
// on every build. Files are named accept-* (a sound input the loader must take) or refuse-* (one it must
// refuse, clearly); header-only.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace multidir::test {

// The regular files of tests/fuzz/<folder>, sorted by name.
inline std::vector<std::filesystem::path> fuzzCorpus(const std::string& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(MULTIDIR_SOURCE_DIR) / "tests" / "fuzz" / folder))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The file's bytes, for the promises that look at what a refusal quotes.
inline std::string corpusText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// True for accept-*, false for refuse-*; anything else is a mistake in the corpus and fails the caller's test.
inline bool corpusSaysAccept(const std::filesystem::path& file) {
  return file.filename().string().rfind("accept-", 0) == 0;
}
inline bool corpusNameIsKnown(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  return name.rfind("accept-", 0) == 0 || name.rfind("refuse-", 0) == 0;
}

}  // namespace multidir::test
