// Replays the corpora of the plan, project and machine-profile fuzzers (tests/fuzz/corpus-plan, corpus-project,
// corpus-machine): each file is loaded or refused as its name says, and a refusal says what and where.
#include <gtest/gtest.h>

#include <filesystem>

#include "multidir/core/plan/plan_file.h"
#include "multidir/core/plan/project_file.h"
#include "support/fuzz_corpus.h"
#include "support/refusal_promise.h"
#include "support/test_models.h"

using namespace multidir::core;
namespace fs = std::filesystem;

namespace {

template <typename T>
void expectAsNamed(const fs::path& file, const Result<T>& loaded) {
  ASSERT_TRUE(multidir::test::corpusNameIsKnown(file)) << "corpus files are named accept-* or refuse-*";
  EXPECT_EQ(multidir::test::brokenRefusalPromise(loaded, multidir::test::corpusText(file)), "");
  if (multidir::test::corpusSaysAccept(file)) {
    EXPECT_TRUE(loaded.ok()) << loaded.error().describe();
  } else {
    EXPECT_FALSE(loaded.ok());
  }
}

}  // namespace

TEST(FileLoaderCorpus, EveryMachineProfileIsLoadedOrRefusedAsItsNameSays) {
  const auto files = multidir::test::fuzzCorpus("corpus-machine");
  ASSERT_GE(files.size(), 5u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    expectAsNamed(file, loadMachineProfile(file.string()));
  }
}

TEST(FileLoaderCorpus, EveryProjectIsLoadedOrRefusedAsItsNameSays) {
  const auto files = multidir::test::fuzzCorpus("corpus-project");
  ASSERT_GE(files.size(), 3u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    expectAsNamed(file, loadProject(file.string()));
  }
}

TEST(FileLoaderCorpus, EveryPlanJsonIsLoadedOrRefusedAsItsNameSays) {
  // The fuzzer's view: the file is the plan.json of a folder that holds nothing else, so even a sound
  // plan.json is refused for its missing region files; accept-* seeds therefore only must fail there.
  const auto files = multidir::test::fuzzCorpus("corpus-plan");
  ASSERT_GE(files.size(), 3u);
  const std::string dir = multidir::test::scratchDirectory("FileLoaderCorpus.Plan");
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    ASSERT_TRUE(multidir::test::corpusNameIsKnown(file));
    fs::copy_file(file, fs::path(dir) / "plan.json", fs::copy_options::overwrite_existing);
    const Result<LoadedPlan> loaded = loadPlan(dir);
    EXPECT_EQ(multidir::test::brokenRefusalPromise(loaded, multidir::test::corpusText(file)), "");
    ASSERT_FALSE(loaded.ok());
    if (multidir::test::corpusSaysAccept(file)) {
      EXPECT_EQ(loaded.error().code, ErrorCode::FileNotFound) << "a sound plan.json fails only for its region files: "
                                                              << loaded.error().describe();
    }
  }
}
