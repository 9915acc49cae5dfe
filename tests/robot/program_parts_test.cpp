// A step's program above the cell's maxProgramBytes split into parts the controller accepts
// (docs/robot-cell.md, "Programs the controller accepts"): each part within the bound, cut only where the
// extruder is idle, the parts' moves together exactly the step's, every later part starting with the step's
// state where it starts. The step: three layers of nine 5 mm squares on the paper cell, each square reached by a
// travel, the fan switched on at layer 2 and the nozzle's set point changed at layer 3.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "multidir/robot/cell.h"
#include "multidir/robot/robot_program.h"
#include "program_parts.h"
#include "step_converter.h"

namespace multidir::robot::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

// travels: each square reached by a travel (else by an extrusion); hops: each travel lifts the nozzle 0.4 mm,
// moves across and lowers it again, as PrusaSlicer's retract_lift writes it.
std::string gcodeOfSquares(bool travels, bool hops = false) {
  std::ostringstream g;
  g.precision(3);
  g << std::fixed << "G90\nM82\nG92 E0\nM104 S215\n";
  double e = 0.0;
  for (int layer = 1; layer <= 3; ++layer) {
    g << ";LAYER_CHANGE\nG1 Z" << 0.4 * layer << " F600\n";
    if (layer == 2) g << "M106 S255\n";
    if (layer == 3) g << "M104 S220\n";
    for (int i = 0; i < 9; ++i) {
      const double x = -10.0 + 10.0 * (i % 3), y = -10.0 + 10.0 * (i / 3);
      if (travels || (layer == 1 && i == 0)) {
        if (hops) g << "G1 Z" << 0.4 * layer + 0.4 << " F6000\n";
        g << "G1 X" << x - 2.5 << " Y" << y - 2.5 << " F6000\n";
        if (hops) g << "G1 Z" << 0.4 * layer << " F6000\n";
      } else {
        e += 0.5;
        g << "G1 X" << x - 2.5 << " Y" << y - 2.5 << " E" << e << " F1200\n";
      }
      const double corners[4][2] = {{2.5, -2.5}, {2.5, 2.5}, {-2.5, 2.5}, {-2.5, -2.5}};
      for (const auto& c : corners) {
        e += 0.2;
        g << "G1 X" << x + c[0] << " Y" << y + c[1] << " E" << e << " F1200\n";
      }
    }
  }
  return g.str();
}

Cell paperCell() {
  auto cell = loadCell(std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json");
  if (!cell) throw std::runtime_error(cell.error().describe());
  return cell.value();
}

std::string convertedSquares(bool travels, bool hops = false) {
  StepInput input;
  input.step = 2;
  input.stepCount = 3;
  input.gcodeFile = "step-02.gcode";
  input.gcode = gcodeOfSquares(travels, hops);
  for (int i = 0; i < 72; ++i) {
    const double a = 2 * kPi * i / 72;
    input.carried.push_back({Eigen::Vector3d(30.0 * std::cos(a), 30.0 * std::sin(a), 0.0), CarriedPoint::Kind::Platform});
  }
  const StepOutput out = convertStep(input, paperCell(), RobotProgramOptions{}, core::JobContext());
  if (!out.refusals.empty()) throw std::runtime_error(out.refusals.front());
  return out.script;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool isMove(const std::string& line) {
  return line.rfind("  movel(", 0) == 0 || line.rfind("  movej(", 0) == 0;
}

// The analog out 0 value in effect at each movel of `text`, in order.
std::vector<double> ratesAtMovels(const std::string& text) {
  std::vector<double> rates;
  double rate = 0.0;
  for (const std::string& line : linesOf(text)) {
    if (line.rfind("  set_standard_analog_out(0, ", 0) == 0) rate = std::stod(line.substr(29));
    if (line.rfind("  movel(", 0) == 0) rates.push_back(rate);
  }
  return rates;
}

constexpr std::size_t kBound = 8000;

TEST(ProgramParts, AStepAboveTheBoundIsSplitIntoCompleteProgramsEachWithinIt) {
  const std::string script = convertedSquares(true);
  ASSERT_GT(script.size(), 2 * kBound);
  const auto parts = splitStepProgram(script, 2, kBound);
  ASSERT_TRUE(parts.ok()) << parts.error().describe();
  EXPECT_GE(parts->size(), 3u);
  for (std::size_t k = 0; k < parts->size(); ++k) {
    const std::string& text = (*parts)[k].text;
    EXPECT_LE(text.size(), kBound) << "part " << k + 1;
    EXPECT_EQ(text.rfind("def multidir_step_02():\n", 0), 0u) << "part " << k + 1;
    EXPECT_EQ(text.substr(text.size() - 4), "end\n") << "part " << k + 1;
  }
  EXPECT_EQ(partFileName(2, 3, static_cast<int>(parts->size())), "step-02-part-003.script");
  EXPECT_EQ(partFileName(2, 1, 1), "step-02.script");
}

TEST(ProgramParts, TheConcatenatedPartsMovesAreExactlyTheUnsplitStepsMovesAndTheirNumbers) {
  const std::string script = convertedSquares(true);
  const auto parts = splitStepProgram(script, 2, kBound);
  ASSERT_TRUE(parts.ok()) << parts.error().describe();
  std::vector<std::string> whole, joined;
  const auto movesAndNumbers = [](const std::string& text, std::vector<std::string>& out) {
    for (const std::string& line : linesOf(text))
      if (isMove(line) || line.rfind("  write_output_integer_register(24, ", 0) == 0) out.push_back(line);
  };
  movesAndNumbers(script, whole);
  int movels = 0;
  for (const ProgramPart& part : *parts) {
    EXPECT_EQ(part.firstMovel, movels + 1);
    movels += part.movels;
    std::vector<std::string> own;
    movesAndNumbers(part.text, own);
    joined.insert(joined.end(), own.begin(), own.end());
  }
  EXPECT_EQ(joined, whole);
  EXPECT_EQ(ratesAtMovels(script).size(), static_cast<std::size_t>(movels));
}

// A part ends before a travel: the extruder stopped through the next part's first movel, the move before it not
// blended into it, and the extruder stopped before the part's end; no movel extrudes at another rate than in
// the unsplit step.
TEST(ProgramParts, PartsAreCutOnlyWhereTheExtruderIsIdle) {
  const std::string script = convertedSquares(true);
  const auto parts = splitStepProgram(script, 2, kBound);
  ASSERT_TRUE(parts.ok()) << parts.error().describe();
  std::vector<double> joinedRates;
  for (std::size_t k = 0; k < parts->size(); ++k) {
    const std::string& text = (*parts)[k].text;
    const std::vector<double> rates = ratesAtMovels(text);
    joinedRates.insert(joinedRates.end(), rates.begin(), rates.end());
    if (k > 0) {
      EXPECT_EQ(rates.front(), 0.0) << "part " << k + 1 << " starts with an extrusion";
    }
    if (k + 1 < parts->size()) {
      const std::vector<std::string> lines = linesOf(text);
      ASSERT_GE(lines.size(), 3u);
      EXPECT_EQ(lines[lines.size() - 2], "  set_standard_analog_out(0, 0.000000)") << "part " << k + 1;
      const std::string& lastMovel = lines[lines.size() - 3];
      ASSERT_EQ(lastMovel.rfind("  movel(", 0), 0u) << lastMovel;
      EXPECT_NE(lastMovel.find(", r=0.000000)"), std::string::npos) << "part " << k + 1 << " ends blended";
    }
  }
  EXPECT_EQ(joinedRates, ratesAtMovels(script));
}

// Where the travels lift the nozzle, a part ends after a travel's lift, not before it: the nozzle waits off the
// printed surface (hot, for as long as the next part takes to send and compile), not resting on it.
TEST(ProgramParts, APartEndsAfterATravelsLiftSoTheNozzleWaitsOffThePrintedSurface) {
  const std::string script = convertedSquares(true, true);
  const auto parts = splitStepProgram(script, 2, kBound);
  ASSERT_TRUE(parts.ok()) << parts.error().describe();
  ASSERT_GE(parts->size(), 3u);
  for (std::size_t k = 0; k + 1 < parts->size(); ++k) {
    const std::vector<double> rates = ratesAtMovels((*parts)[k].text);
    ASSERT_FALSE(rates.empty());
    EXPECT_EQ(rates.back(), 0.0) << "part " << k + 1 << " ends on an extrusion, its nozzle on the part";
  }
}

// Every later part sets the tool, the extruder (stopped), the nozzle's set point and the fan as the step has
// them where the part starts.
TEST(ProgramParts, EachLaterPartStartsWithTheStepsToolFanAndSetPointThere) {
  const std::string script = convertedSquares(true);
  const auto parts = splitStepProgram(script, 2, kBound);
  ASSERT_TRUE(parts.ok()) << parts.error().describe();
  ASSERT_GE(parts->size(), 3u);
  std::string tcp, setPoint, fan;
  for (std::size_t k = 0; k < parts->size(); ++k) {
    const std::vector<std::string> lines = linesOf((*parts)[k].text);
    if (k > 0) {
      // The first of each in the part: its opening's (a change the G-code makes where the part starts, as at a
      // layer's M104, follows it).
      std::string partTcp, partSetPoint, partFan;
      for (std::size_t i = 1; i < lines.size() && !isMove(lines[i]) &&
                              lines[i].rfind("  write_output_integer_register", 0) != 0;
           ++i) {
        if (partTcp.empty() && lines[i].rfind("  set_tcp(", 0) == 0) partTcp = lines[i];
        if (partSetPoint.empty() && lines[i].rfind("  set_standard_analog_out(1, ", 0) == 0) partSetPoint = lines[i];
        if (partFan.empty() && lines[i].rfind("  set_standard_digital_out(0, ", 0) == 0) partFan = lines[i];
      }
      EXPECT_EQ(partTcp, tcp) << "part " << k + 1;
      EXPECT_EQ(partSetPoint, setPoint) << "part " << k + 1;
      EXPECT_EQ(partFan, fan) << "part " << k + 1;
      EXPECT_EQ(lines[2 + (tcp.empty() ? 0 : 1)], "  set_standard_analog_out(0, 0.000000)") << "part " << k + 1;
    }
    for (const std::string& line : lines) {
      if (line.rfind("  set_tcp(", 0) == 0) tcp = line;
      if (line.rfind("  set_standard_analog_out(1, ", 0) == 0) setPoint = line;
      if (line.rfind("  set_standard_digital_out(0, ", 0) == 0) fan = line;
    }
  }
  // The step's state changes at layers 2 and 3: the later parts carry different ones.
  EXPECT_NE(fan, "");
  EXPECT_NE(setPoint, "");
}

TEST(ProgramParts, AStepWithinTheBoundStaysOneProgram) {
  const std::string script = convertedSquares(true);
  const auto parts = splitStepProgram(script, 2, script.size() + kResumeReserveBytes);
  ASSERT_TRUE(parts.ok()) << parts.error().describe();
  ASSERT_EQ(parts->size(), 1u);
  EXPECT_EQ(parts->front().text, script);
}

// Squares joined by extrusions, no travel after the first: nowhere to cut within the bound.
TEST(ProgramParts, ExtrusionWithoutATravelLongerThanAPartIsRefusedNamingTheStepAndTheBound) {
  const std::string script = convertedSquares(false);
  const auto parts = splitStepProgram(script, 2, kBound);
  ASSERT_FALSE(parts.ok());
  EXPECT_EQ(parts.error().code, core::ErrorCode::CheckFailed);
  EXPECT_NE(parts.error().message.find("step 2"), std::string::npos) << parts.error().message;
  EXPECT_NE(parts.error().message.find("maxProgramBytes"), std::string::npos) << parts.error().message;
}

TEST(ProgramParts, CellCheckRefusesABoundTooSmallForAPart) {
  Cell cell = paperCell();
  EXPECT_EQ(cell.maxProgramBytes, 100000u);
  cell.maxProgramBytes = kMinProgramBytes - 1;
  bool named = false;
  for (const CellProblem& p : checkCell(cell)) named = named || p.key == "maxProgramBytes";
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace multidir::robot::detail
