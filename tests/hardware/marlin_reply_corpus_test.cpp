// Replays the Marlin reply fuzzer's corpus (tests/fuzz/corpus-marlin_reply): every line is parsed, a resend
// names a line or none (-1), and a temperature read from a line is one a sensor can read (line noise never
// becomes a reading).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "printer/marlin_protocol.h"
#include "printer/plausible_reading.h"
#include "support/fuzz_corpus.h"

namespace fs = std::filesystem;
using multidir::hardware::marlin::parseReply;
using multidir::hardware::marlin::Reply;

TEST(FileLoaderCorpus, EveryMarlinLineParsesToAReadingASensorCanGive) {
  const auto files = multidir::test::fuzzCorpus("corpus-marlin_reply");
  ASSERT_GE(files.size(), 1u);
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
      SCOPED_TRACE(line);
      const Reply reply = parseReply(line);
      if (reply.kind == Reply::Kind::Resend) {
        EXPECT_GE(reply.resendLine, -1) << "a resend names a line or none (-1)";
      }
      for (const auto& heater : {reply.extruder, reply.bed}) {
        if (heater) {
          EXPECT_TRUE(multidir::hardware::plausibleCelsius(heater->actualC) && multidir::hardware::plausibleCelsius(heater->targetC));
        }
      }
    }
  }
}
