// Replays the printer-profile fuzzer's corpus (tests/fuzz/corpus-printer): each .ini is loaded or refused as
// its name says, and a refusal says what and where.
#include <gtest/gtest.h>

#include <filesystem>

#include "multidir/slicing/printer_profile.h"
#include "support/fuzz_corpus.h"
#include "support/refusal_promise.h"

namespace fs = std::filesystem;

TEST(FileLoaderCorpus, EveryPrinterProfileIsLoadedOrRefusedAsItsNameSays) {
  const auto files = multidir::test::fuzzCorpus("corpus-printer");
  ASSERT_GE(files.size(), 5u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    ASSERT_TRUE(multidir::test::corpusNameIsKnown(file)) << "corpus files are named accept-* or refuse-*";
    const auto loaded = multidir::slicing::loadPrinterProfile(file.string());
    EXPECT_EQ(multidir::test::brokenRefusalPromise(loaded, multidir::test::corpusText(file)), "");
    if (multidir::test::corpusSaysAccept(file)) {
      EXPECT_TRUE(loaded.ok()) << loaded.error().describe();
    } else {
      EXPECT_FALSE(loaded.ok());
    }
  }
}
