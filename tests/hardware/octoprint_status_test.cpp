// OctoPrint's replies read and its states mapped onto PrinterJobState: the table in docs/hardware.md,
// "OctoPrint", row by row, including the states the simulator never shows (Cancelling, Offline, ...).
#include "printer/octoprint_status.h"

#include <gtest/gtest.h>

#include <vector>

namespace multidir::hardware {
namespace {

using Json = nlohmann::json;

OctoPrintJobReading job(const std::string& state, const std::string& file = "step-01.gcode",
                        std::optional<double> completion = std::nullopt, const std::string& error = "") {
  OctoPrintJobReading r;
  r.stateText = state;
  r.file = file;
  r.completion = completion;
  r.error = error;
  return r;
}

struct MappingCase {
  std::string state;
  PrinterJobState expected;
  std::string firmwareState;
};

TEST(OctoPrintStatus, EachStateStringMapsAsTheTableSays) {
  const std::vector<MappingCase> cases = {
      {"Printing", PrinterJobState::Printing, "ready"},
      {"Starting", PrinterJobState::Printing, "ready"},
      {"Pausing", PrinterJobState::Printing, "ready"},
      {"Resuming", PrinterJobState::Printing, "ready"},
      {"Finishing", PrinterJobState::Printing, "ready"},
      {"Cancelling", PrinterJobState::Printing, "ready"},
      {"Printing from SD", PrinterJobState::Printing, "ready"},
      {"Sending file to SD", PrinterJobState::Printing, "ready"},
      {"Paused", PrinterJobState::Paused, "ready"},
      {"Operational", PrinterJobState::Standby, "ready"},
      {"Error", PrinterJobState::Error, "error"},
      {"Offline after error", PrinterJobState::Error, "error"},
      {"Offline (Error: Too many consecutive timeouts)", PrinterJobState::Error, "error"},
      {"Offline", PrinterJobState::Standby, "offline"},
      {"Closed", PrinterJobState::Standby, "offline"},
      {"Opening serial connection", PrinterJobState::Standby, "connecting"},
      {"Detecting baudrate", PrinterJobState::Standby, "connecting"},
      {"Reconnecting", PrinterJobState::Standby, "connecting"},
  };
  for (const MappingCase& c : cases) {
    OctoPrintJobTracker tracker;  // fresh: no job seen before
    const PrinterReading r = tracker.read(job(c.state), nullptr);
    EXPECT_EQ(r.state, c.expected) << c.state;
    EXPECT_EQ(r.firmwareState, c.firmwareState) << c.state;
  }
}

// Issue 28: a word outside the table read as an idle printer (standby), and the run moved.
TEST(OctoPrintStatus, AStateWordOutsideTheTableReadsUnknownNamingTheWord) {
  for (const std::string word : {"Unknown State (42)", "Unknown", "Calibrating", ""}) {
    OctoPrintJobTracker tracker;
    const PrinterReading r = tracker.read(job(word), nullptr);
    EXPECT_EQ(r.state, PrinterJobState::Unknown) << word;
    EXPECT_EQ(r.firmwareState, "unknown") << word;
    EXPECT_NE(r.message.find("'" + word + "'"), std::string::npos) << r.message;
  }
}

TEST(OctoPrintStatus, OperationalAtFullCompletionIsCompleteAndShortOfItAfterPrintingIsCancelled) {
  OctoPrintJobTracker finished;
  EXPECT_EQ(finished.read(job("Printing", "a.gcode", 40.0), nullptr).state, PrinterJobState::Printing);
  EXPECT_EQ(finished.read(job("Operational", "a.gcode", 100.0), nullptr).state, PrinterJobState::Complete);
  EXPECT_EQ(finished.read(job("Operational", "a.gcode", 100.0), nullptr).state, PrinterJobState::Complete);

  OctoPrintJobTracker cancelled;
  EXPECT_EQ(cancelled.read(job("Printing", "a.gcode", 40.0), nullptr).state, PrinterJobState::Printing);
  EXPECT_EQ(cancelled.read(job("Operational", "a.gcode"), nullptr).state, PrinterJobState::Cancelled);
  EXPECT_EQ(cancelled.read(job("Operational", "a.gcode"), nullptr).state, PrinterJobState::Cancelled);  // stays
  EXPECT_EQ(cancelled.read(job("Operational", "b.gcode"), nullptr).state, PrinterJobState::Standby);    // selected
}

TEST(OctoPrintStatus, AFileNeverSeenPrintingAndNotCompleteIsStandby) {
  OctoPrintJobTracker tracker;
  EXPECT_EQ(tracker.read(job("Operational", "a.gcode", 35.0), nullptr).state, PrinterJobState::Standby);
  EXPECT_EQ(tracker.read(job("Operational", ""), nullptr).state, PrinterJobState::Standby);
}

TEST(OctoPrintStatus, AnErrorQuotesOctoPrintsErrorAndAFlagOverridesTheText) {
  OctoPrintJobTracker tracker;
  const PrinterReading r = tracker.read(
      job("Offline after error", "a.gcode", 12.0, "MAXTEMP triggered, system stopped! Heater_ID: 0"), nullptr);
  EXPECT_EQ(r.state, PrinterJobState::Error);
  EXPECT_EQ(r.message, "MAXTEMP triggered, system stopped! Heater_ID: 0");
  OctoPrintPrinterReading printer;
  printer.operational = true;
  printer.error = true;
  EXPECT_EQ(tracker.read(job("Operational"), &printer).state, PrinterJobState::Error);
}

TEST(OctoPrintStatus, HeatersAreTheLastReadWhileOctoPrintHasNoConnectionToThePrinter) {
  OctoPrintJobTracker tracker;
  OctoPrintPrinterReading printer;
  printer.tool0 = {205.0, 210.0};
  printer.bed = {60.0, 60.0};
  EXPECT_DOUBLE_EQ(tracker.read(job("Printing"), &printer).extruder.actualC, 205.0);
  const PrinterReading offline = tracker.read(job("Offline after error"), nullptr);
  EXPECT_DOUBLE_EQ(offline.extruder.actualC, 205.0);
  EXPECT_DOUBLE_EQ(offline.bed.targetC, 60.0);
}

TEST(OctoPrintStatus, ReadsTheDocumentedReplyShapesAndRefusesOthers) {
  const Json jobReply = Json::parse(R"({"job": {"file": {"name": "whistle_v2.gcode", "origin": "local"}},
      "progress": {"completion": 22.98, "filepos": 337942}, "state": "Printing"})");
  const auto j = readOctoPrintJob(jobReply, "test printer");
  ASSERT_TRUE(j.ok());
  EXPECT_EQ(j->file, "whistle_v2.gcode");
  EXPECT_DOUBLE_EQ(j->completion.value(), 22.98);
  EXPECT_EQ(j->error, "");
  const Json idle = Json::parse(R"({"job": {"file": {"name": null}}, "progress": {"completion": null},
      "state": "Operational"})");
  ASSERT_TRUE(readOctoPrintJob(idle, "p").ok());
  EXPECT_FALSE(readOctoPrintJob(idle, "p")->completion.has_value());
  const Json printerReply = Json::parse(R"({"temperature": {"tool0": {"actual": 214.8, "target": 220.0, "offset": 0},
      "bed": {"actual": 50.2, "target": 70.0, "offset": 5}}, "state": {"text": "Operational",
      "flags": {"operational": true, "paused": false, "printing": false, "error": false, "ready": true}}})");
  const auto p = readOctoPrintPrinter(printerReply, "p");
  ASSERT_TRUE(p.ok());
  EXPECT_TRUE(p->operational);
  EXPECT_DOUBLE_EQ(p->tool0.targetC, 220.0);
  EXPECT_DOUBLE_EQ(p->bed.actualC, 50.2);
  EXPECT_NE(readOctoPrintJob(Json::parse(R"({"result": "ok"})"), "p").error().message.find("is this OctoPrint"),
            std::string::npos);
  EXPECT_FALSE(readOctoPrintPrinter(Json::parse(R"({"state": "Operational"})"), "p").ok());
}

}  // namespace
}  // namespace multidir::hardware
