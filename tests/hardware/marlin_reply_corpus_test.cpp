// Replays the Marlin reply fuzzer's corpus (tests/fuzz/corpus-marlin_reply): every line is parsed, a resend
// names a line or none (-1), and a temperature read from a line is one a sensor can read (line noise never
// becomes a reading).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/fuzz_corpus.h"
#include "support/marlin_reply_promise.h"

namespace fs = std::filesystem;

TEST(FileLoaderCorpus, EveryMarlinLineParsesToAReadingASensorCanGive) {
  const auto files = multidir::test::fuzzCorpus("corpus-marlin_reply");
  ASSERT_GE(files.size(), 1u);
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) EXPECT_EQ(multidir::test::brokenMarlinReplyPromise(line), "") << line;
  }
}
