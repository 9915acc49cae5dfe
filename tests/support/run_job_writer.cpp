#include "support/run_job_writer.h"

#include <filesystem>
#include <fstream>

namespace multidir::test {

std::string stepGcode(int step, bool heatersLeftOn) {
  std::string text = std::string(heatersLeftOn ? "M140 S60\n" : "") + "M104 S200\nM109 S200\nG90\nM83\n" +
                     "; MULTIDIR STEP " + std::to_string(step) + "\nG1 X0 Y0 Z0.3 F1200\n";
  for (int i = 0; i < 20; ++i) text += "G1 X" + std::to_string((i + 1) % 2 * 10) + " Y" + std::to_string(i) + " E0.5\n";
  return text + (heatersLeftOn ? "" : "M104 S0\n");
}

std::string platformProfileBeside(const std::string& dir) {
  return (std::filesystem::path(dir).parent_path() / "platform.json").string();
}

void writeRotaryProfile(const std::string& path, double minDegrees, double maxDegrees) {
  std::ofstream(path) << "{\"schema\": \"multidir-machine\", \"version\": 1, \"kind\": \"4dof\", \"up\": [0, 0, 1], "
                         "\"rotationAxis\": [1, 0, 0], \"minAngleDegrees\": "
                      << minDegrees << ", \"maxAngleDegrees\": " << maxDegrees << ", \"angleStepDegrees\": 1}\n";
}

void writeJob(const std::string& dir, bool sliced, bool robot, bool heatersLeftOn) {
  std::filesystem::create_directories(dir);
  std::string steps;
  std::string slicing;
  const double angles[2] = {0.0, heatersLeftOn ? 90.0 : 30.0};  // a long turn to press Ctrl-C in
  for (int k = 1; k <= 2; ++k) {
    const std::string gcode = "step-0" + std::to_string(k) + ".gcode";
    std::ofstream(dir + "/" + gcode) << stepGcode(k, heatersLeftOn);
    const std::string stepAngles = robot ? (k == 1 ? "{\"tiltDegrees\": 0, \"azimuthDegrees\": 0}"
                                                   : "{\"tiltDegrees\": 40, \"azimuthDegrees\": 90}")
                                         : "{\"rotaryDegrees\": " + std::to_string(angles[k - 1]) + "}";
    steps += std::string(k > 1 ? "," : "") + "{\"index\": " + std::to_string(k) + ", \"angles\": " + stepAngles + "}";
    slicing += std::string(k > 1 ? "," : "") + "{\"index\": " + std::to_string(k) + ", \"gcode\": \"" + gcode +
               "\", \"estimate\": {\"printSeconds\": 28, \"filamentMm\": 10, \"filamentCm3\": 0.02, "
               "\"filamentGrams\": 0}, \"baseZMm\": 0}";
  }
  const std::string machine = robot ? "{\"kind\": \"5dof\", \"up\": [0, 0, 1], \"maxTiltDegrees\": 60}"
                                    : "{\"kind\": \"4dof\", \"up\": [0, 0, 1], \"rotationAxis\": [1, 0, 0], "
                                      "\"minAngleDegrees\": -90, \"maxAngleDegrees\": 90, \"angleStepDegrees\": 1}";
  std::ofstream(dir + "/print-job.json")
      << "{\"schema\": \"multidir-print-job\", \"version\": 1, \"machine\": " << machine << ", \"steps\": [" << steps
      << "]"
      << (sliced
              ? ", \"slicing\": {\"printer\": {\"profile\": \"marlin-220\", \"platform\": \"modbus\"}, \"steps\": [" +
                    slicing +
                    "], \"turns\": [{\"fromStep\": 1, \"fromDegrees\": 0, \"toDegrees\": 30, "
                    "\"sweptTopZMm\": 0, \"clearanceZMm\": 0}]}"
              : "")
      << "}\n";
  if (robot)
    std::ofstream(platformProfileBeside(dir))
        << "{\"schema\": \"multidir-machine\", \"version\": 1, \"kind\": \"5dof\", "
           "\"up\": [0, 0, 1], \"maxTiltDegrees\": 60}\n";
  else
    writeRotaryProfile(platformProfileBeside(dir), -90.0, 90.0);
}

}  // namespace multidir::test
