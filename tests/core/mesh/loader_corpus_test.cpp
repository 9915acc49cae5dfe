// Replays the loader corpus (tests/fuzz/corpus, written by scripts/make_loader_corpus.py and the seeds of
// the libFuzzer harness) through loadMesh: accept-* must load as sound solids, refuse-* must be refused,
// and every file read as any of the four formats must keep loadMesh's promise.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

#include "multidir/core/mesh/mesh_io.h"
#include "support/loader_promises.h"
#include "support/test_models.h"

using namespace multidir::core;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> corpusFiles() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(MULTIDIR_SOURCE_DIR) / "tests" / "fuzz" / "corpus"))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

}  // namespace

TEST(LoaderCorpus, HoldsTheHostileInputsOfIssue14) {
  const std::vector<fs::path> files = corpusFiles();
  ASSERT_GE(files.size(), 30u);
  for (const char* name : {"refuse-off-coordinate-1e39.off", "refuse-off-coordinate-hex.off",
                           "refuse-off-overlapping-shells.off", "refuse-off-flat-tetrahedron.off",
                           "refuse-off-double-cone.off", "refuse-ply-binary-coordinate-1e39.ply"})
    EXPECT_TRUE(std::any_of(files.begin(), files.end(), [&](const fs::path& p) { return p.filename() == name; }))
        << name;
  for (const fs::path& file : files) EXPECT_LE(fs::file_size(file), 8192u) << file << " is not small";
}

TEST(LoaderCorpus, EveryFileIsAcceptedOrRefusedAsItsNameSays) {
  for (const fs::path& file : corpusFiles()) {
    const std::string name = file.filename().string();
    SCOPED_TRACE(name);
    const Result<LoadedMesh> loaded = loadMesh(file.string());
    EXPECT_EQ(multidir::test::brokenLoaderPromise(loaded), "");
    if (startsWith(name, "accept-")) {
      EXPECT_TRUE(loaded.ok()) << loaded.error().describe();
    } else {
      ASSERT_TRUE(startsWith(name, "refuse-")) << "corpus files are named accept-* or refuse-*";
      EXPECT_FALSE(loaded.ok()) << "loaded with volume " << loaded->report.statistics.volumeMm3;
    }
  }
}

TEST(LoaderCorpus, EveryFileReadAsAnyFormatKeepsTheLoadersPromise) {
  // The fuzzer's view: the same bytes under every extension.
  const std::string dir = multidir::test::scratchDirectory("LoaderCorpus.AnyFormat");
  for (const fs::path& file : corpusFiles())
    for (const char* extension : {"stl", "obj", "off", "ply"}) {
      SCOPED_TRACE(file.filename().string() + " as ." + extension);
      const fs::path copy = fs::path(dir) / (std::string("input.") + extension);
      fs::copy_file(file, copy, fs::copy_options::overwrite_existing);
      EXPECT_EQ(multidir::test::brokenLoaderPromise(loadMesh(copy.string())), "");
    }
}
