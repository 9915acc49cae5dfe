#include "run_job_checks.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "cli_args.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/hardware/content_digest.h"
#include "multidir/hardware/motion_limits.h"
#include "multidir/slicing/step_recheck.h"

namespace multidir::cli {
namespace {

namespace fs = std::filesystem;

// A step's G-code beyond this is no slicer's output for one region: refused rather than read into memory.
constexpr off_t kMaxGcodeBytes = off_t{1} << 30;

[[noreturn]] void bad(const std::string& file, const std::string& what) {
  throw FileError("multidir run: " + file + ": " + what);
}

// The whole file, opened without following a link and only when it is a regular file (checked on the file
// opened, so nothing swapped in after readRunJob's look is read instead). O_NONBLOCK: a FIFO swapped in
// cannot hang the command.
std::string readGcode(const RunJobStep& step) {
  const int fd = ::open(step.gcodePath.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    bad(step.gcodePath, std::string("cannot be opened (") + std::strerror(errno) + ") for step " +
                            std::to_string(step.index) + ": it must be a regular file, not a link");
  struct stat info {};
  std::string text;
  std::string problem;
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode))
    problem = "is not a regular file: give the G-code file 'multidir slice' wrote";
  else if (info.st_size > kMaxGcodeBytes)
    problem = "has " + std::to_string(info.st_size) + " bytes, more than the 1 GiB a step's G-code may have";
  char buffer[1 << 16];
  while (problem.empty()) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      problem = std::string("cannot be read (") + std::strerror(errno) + ")";
      break;
    }
    text.append(buffer, static_cast<std::size_t>(n));
    if (static_cast<off_t>(text.size()) > kMaxGcodeBytes) problem = "grew beyond 1 GiB while it was read";
  }
  ::close(fd);
  if (!problem.empty()) bad(step.gcodePath, problem + " (step " + std::to_string(step.index) + "'s G-code)");
  return text;
}

// Whether the platform can take the step's angles; the refusal names the limit and its range.
core::Status platformTakes(const core::MachineSpec& platform, const hardware::PlatformOrientation& o) {
  if (o.kind == hardware::PlatformOrientation::Kind::Rotary)
    return hardware::checkRotaryTarget(platform, o.rotaryDegrees);
  return hardware::checkTiltTarget(platform, o.tiltDegrees, o.azimuthDegrees);
}

// The field of the angle a refusal names.
std::string angleField(const RunJobStep& step, const core::Error& error) {
  if (step.orientation.kind == hardware::PlatformOrientation::Kind::Rotary) return step.anglesField + ".rotaryDegrees";
  if (error.where == "tilt") return step.anglesField + ".tiltDegrees";
  return step.anglesField + " (tiltDegrees, azimuthDegrees)";
}

}  // namespace

core::MachineSpec loadPlatformProfile(const std::string& path) {
  const core::Result<core::MachineSpec> profile = core::loadMachineProfile(path);
  if (!profile)
    throw FileError("multidir run: --machine " + path + ": " + profile.error().describe() +
                    ": give the machine profile (JSON, as 'multidir decompose --profile' reads) of the connected "
                    "platform");
  return *profile;
}

slicing::PrinterProfile loadRunPrinterProfile(const RunJob& job, const std::string& option) {
  if (!option.empty()) {
    const core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile(option);
    if (!profile) throw FileError("multidir run: --printer-profile " + option + ": " + profile.error().describe());
    return *profile;
  }
  if (job.printerProfile.empty())
    bad(job.jobFile,
        "slicing.printer.profile is missing: give --printer-profile NAME|FILE, the printer profile the job was "
        "sliced with (its G-code is checked against the printer's bed and height before anything moves)");
  core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile(job.printerProfile);
  // A profile named by a relative path was found from where `multidir slice` ran: try beside the job too.
  const fs::path beside = fs::path(job.folder) / job.printerProfile;
  std::error_code ec;
  if (!profile && fs::path(job.printerProfile).is_relative() && fs::is_regular_file(beside, ec))
    profile = slicing::loadPrinterProfile(beside.string());
  if (!profile)
    bad(job.jobFile, "slicing.printer.profile '" + job.printerProfile + "' cannot be read (" +
                         profile.error().describe() +
                         "): give --printer-profile NAME|FILE, the printer profile the job was sliced with");
  return *profile;
}

std::vector<std::string> checkRunJob(const RunJob& job, const core::MachineSpec& platform, const std::string& platformSource,
                 const slicing::PrinterProfile& printer) {
  if (platform.kind != job.machine.kind)
    bad(job.jobFile, std::string("machine.kind is ") + core::machineKindName(job.machine.kind) +
                         ", but the platform's profile (" + platformSource + ") is a " +
                         core::machineKindName(platform.kind) +
                         " machine: give the profile of the platform this job was planned for");
  // Every step's angles first: a job the platform cannot finish is refused before step 1 is homed or turned.
  for (const RunJobStep& step : job.steps)
    if (core::Status takes = platformTakes(platform, step.orientation); !takes)
      bad(job.jobFile, angleField(step, takes.error()) + " (step " + std::to_string(step.index) +
                           "): " + takes.error().message + " (" + platformSource +
                           "): nothing was moved; plan and slice the job for this platform");
  std::vector<slicing::StepProgramText> programs;
  std::vector<std::string> digests;
  for (const RunJobStep& step : job.steps) {
    slicing::StepProgramText p;
    p.step = step.index;
    p.fileName = fs::path(step.gcodePath).filename().string();
    p.text = readGcode(step);
    digests.push_back(hardware::sha256Hex(p.text));
    p.baseZMm = step.baseZMm;
    p.endClearanceZMm = step.turnClearanceZMm;
    programs.push_back(std::move(p));
  }
  if (core::Status checked = slicing::recheckStepPrograms(programs, printer); !checked)
    bad((fs::path(job.folder) / checked.error().where).string(),
        checked.error().message + " by the checks 'multidir slice' runs (printer profile " + printer.name +
            "): nothing was moved; slice the job again rather than edit its G-code");
  return digests;
}

}  // namespace multidir::cli
