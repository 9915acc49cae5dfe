// Replays the printer-reply fuzzer's corpus (tests/fuzz/corpus-printer_reply): every reply, sound or hostile,
// is refused with a message or read into numbers a printer can report by Moonraker's and OctoPrint's readers.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/fuzz_corpus.h"
#include "support/printer_reply_promise.h"

TEST(FileLoaderCorpus, EveryPrinterReplyIsReadIntoNumbersAPrinterCanReportOrRefused) {
  const auto files = multidir::test::fuzzCorpus("corpus-printer_reply");
  ASSERT_GE(files.size(), 5u);
  for (const std::filesystem::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    EXPECT_EQ(multidir::test::brokenPrinterReplyPromise(multidir::test::corpusText(file)), "");
  }
}
