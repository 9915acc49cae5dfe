#include "run_stitched.h"

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cli_args.h"
#include "multidir/hardware/content_digest.h"

namespace multidir::cli {
namespace {

namespace fs = std::filesystem;

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError("multidir run: " + path + " cannot be read: check its permissions");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

int StitchedRun::stepAt(double progress) const {
  const double byte = std::clamp(progress, 0.0, 1.0) * static_cast<double>(bytes);
  int step = from;
  for (std::size_t i = 1; i < stepBegins.size(); ++i)
    if (byte >= static_cast<double>(stepBegins[i])) step = from + static_cast<int>(i);
  return step;
}

StitchedRun prepareStitchedRun(const RunJob& job, int from) {
  const RunStitchedProgram& stitched = *job.stitched;
  StitchedRun run;
  run.from = from;
  run.steps = static_cast<int>(stitched.stepEstimateSeconds.size());
  std::string text = readAll(stitched.gcodePath);
  run.axes = axesTheProgramUses(text);
  run.remoteName = stitched.gcodeName;
  run.uploadPath = stitched.gcodePath;
  if (from > 1) {
    text = resumedStitchedProgram(text, from, stitched.gcodePath);
    char folder[] = "/tmp/multidir-run-XXXXXX";
    if (::mkdtemp(folder) == nullptr)
      throw FileError("multidir run: cannot make a temporary folder for the program resumed at step " +
                      std::to_string(from) + ": check /tmp");
    run.temporaryFolder = std::shared_ptr<const std::string>(new std::string(folder), [](const std::string* path) {
      std::error_code ignored;
      fs::remove_all(*path, ignored);
      delete path;
    });
    char name[32];
    std::snprintf(name, sizeof name, "job-from-%02d.gcode", from);
    run.remoteName = name;
    run.uploadPath = (fs::path(folder) / name).string();
    std::ofstream outFile(run.uploadPath, std::ios::binary);
    outFile << text;
    if (!outFile.flush())
      throw FileError("multidir run: cannot write " + run.uploadPath + ": check the free space in /tmp");
  }
  run.sha256 = hardware::sha256Hex(text);
  run.bytes = text.size();
  for (int k = from; k <= run.steps; ++k) {
    const std::string marker = "; MULTIDIR STEP " + std::to_string(k) + "\n";
    const std::size_t at = text.find(marker);
    if (at == std::string::npos)
      throw FileError("multidir run: " + stitched.gcodePath + " lacks the line '; MULTIDIR STEP " + std::to_string(k) +
                      "' for step " + std::to_string(k) + " of " + std::to_string(run.steps) +
                      " (print-job.json): it is not the stitched program of this job; slice the job again");
    run.stepBegins.push_back(at);
    run.estimates.push_back(stitched.stepEstimateSeconds[static_cast<std::size_t>(k - 1)]);
  }
  return run;
}

std::string checkPrinterHasTheAxes(hardware::PrinterLink& printer, const StitchedProgramAxes& axes,
                                   bool axesConfirmed) {
  const std::string uses =
      "the program turns " + (axes.manualSteppers.empty() ? "the axes " + joined(axes.letters)
                                                          : "the manual steppers " + joined(axes.manualSteppers));
  std::future<core::Result<hardware::FirmwareAxes>> asked = printer.readFirmwareAxes();
  if (asked.wait_for(std::chrono::seconds(10)) != std::future_status::ready)
    throw std::runtime_error(printer.name() + " did not say which axes it has within 10 s: check it, then run again");
  const core::Result<hardware::FirmwareAxes> has = asked.get();
  if (!has) {
    if (has.error().code != core::ErrorCode::InvalidParameter || printer.name().rfind("OctoPrint", 0) != 0)
      throw std::runtime_error("asking " + printer.name() + " which axes it has failed: " + has.error().describe());
    if (!axesConfirmed)
      throw std::runtime_error(
          uses +
          ", but OctoPrint cannot be asked which axes the printer behind it has (it relays no firmware reply "
          "to its API): check that the printer's firmware has them (Marlin: M114 in OctoPrint's terminal lists "
          "them after Z), then run again with --yes-axes-configured");
    return uses + "; OctoPrint cannot be asked which axes the printer has: --yes-axes-configured says it has them";
  }
  for (const std::string& stepper : axes.manualSteppers)
    if (std::find(has->manualSteppers.begin(), has->manualSteppers.end(), stepper) == has->manualSteppers.end())
      throw std::runtime_error(
          uses + ", but Klipper has no [manual_stepper " + stepper + "] (it has " +
          (has->manualSteppers.empty() ? std::string("none") : joined(has->manualSteppers)) +
          "): add the section to printer.cfg, or slice the job for a profile naming Klipper's steppers "
          "(multidir.klipper_stepper, multidir.klipper_tilt_stepper, multidir.klipper_rotation_stepper)");
  for (const std::string& letter : axes.letters)
    if (std::find(has->letters.begin(), has->letters.end(), letter) == has->letters.end())
      throw std::runtime_error(
          uses + ", but the printer's M114 reports no " + letter + " axis (it reports " +
          (has->letters.empty() ? std::string("X, Y, Z and E only") : "X, Y, Z, " + joined(has->letters) + " and E") +
          "): configure the axis in the firmware (Marlin: AXIS4_NAME ...; RepRapFirmware: M584), or slice the job "
          "for a profile naming the printer's axis letters");
  return uses + "; the printer has " +
         (axes.manualSteppers.empty() ? "them (M114)" : "them ([manual_stepper]s Moonraker lists)");
}

}  // namespace multidir::cli
