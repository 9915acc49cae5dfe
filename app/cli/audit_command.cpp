#include "audit_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "multidir/core/common/atomic_file.h"
#include "multidir/slicing/audit.h"

namespace multidir::cli {

const char* const kAuditHelp =
    "Usage: multidir audit JOB [--json OUT] [--strict] [--alpha DEGREES]\n"
    "\n"
    "Checks a job folder written by 'multidir slice' independently of the slicing: replays its G-code (every\n"
    "step-NN.gcode, one after another as the machine runs them, and job.gcode when the platform is a firmware\n"
    "axis) through the machine's kinematics into the model's frame and checks, per step and in total:\n"
    "  (a) every extrusion lies inside its region or its supports, within half a line width;\n"
    "  (b) every extrusion rests on the platform or on plastic printed before it, within the printable angle\n"
    "      (unsupported length, what J_G predicts: reported, a failure only with --strict);\n"
    "  (c) each step's first layer lies one layer height above its base plane (within 0.05 mm);\n"
    "  (d) nothing is extruded while the filament is retracted;\n"
    "  (e) while the platform turns the nozzle stays above everything printed so far.\n"
    "It also checks that print-job.json's poses agree with the machine angles. Definitions: docs/slicing.md,\n"
    "\"Audit\".\n"
    "\n"
    "Options:\n"
    "  --json OUT         also write the results as JSON to OUT\n"
    "  --strict           unsupported extrusion (b) fails the audit too\n"
    "  --alpha DEGREES    the printable angle for (b) (default: the plan's alphaMaxDegrees, else 45)\n"
    "  -h, --help         show this help\n"
    "\n"
    "Exit codes: 0 the job passes, 1 the job cannot be read, 2 usage error, 5 the audit found a violation.\n";

namespace {

namespace core = multidir::core;
namespace slicing = multidir::slicing;
using Json = nlohmann::ordered_json;

const std::string kCommand = "multidir audit";

std::string number(double value, int digits) {
  if (std::isnan(value)) return "-";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

std::string gapText(const slicing::StepAudit& s) {
  if (std::isnan(s.firstLayerGapMm)) return "-";
  return number(s.firstLayerGapMm, 3) + "/" + number(s.expectedGapMm, 2) + (s.firstLayerViolation ? " !" : "");
}

void printRow(std::ostream& out, const std::string& label, const slicing::StepAudit& s) {
  char line[320];
  std::snprintf(line, sizeof line, "  %-5s %-14s %11.1f %10.2f %9s %12.1f %7.2f %15s %8d %11s\n", label.c_str(),
                s.file.c_str(), s.extrusionMm, s.outsideMm, number(s.worstOutsideMm, 2).c_str(), s.unsupportedMm,
                s.unsupportedPercent(), gapText(s).c_str(), s.retractViolations,
                (number(s.turnClearanceMm, 2) + (s.turnViolation ? " !" : "")).c_str());
  out << line;
}

void printPlaces(std::ostream& out, const char* what, const std::vector<slicing::AuditPlace>& places, bool distance) {
  if (places.empty()) return;
  out << "    " << what << ":\n";
  for (const slicing::AuditPlace& p : places) {
    char line[256];
    std::snprintf(line, sizeof line, "      step %d, %s line %d: %.1f mm near model (%.1f, %.1f, %.1f)%s\n", p.step,
                  p.file.c_str(), p.line, p.lengthMm, p.modelPoint.x(), p.modelPoint.y(), p.modelPoint.z(),
                  distance ? (", up to " + number(p.worstMm, 2) + " mm outside").c_str() : "");
    out << line;
  }
}

void printReport(std::ostream& out, const std::string& job, const slicing::AuditReport& report) {
  out << "Audit of " << job << " (printable angle " << number(report.alphaMaxDegrees, 1) << " degrees)\n";
  for (const slicing::ProgramAudit& program : report.programs) {
    out << "\n" << program.name << (program.stitched ? " (stitched, " + program.followedAxes + " as replayed)" : std::string()) << "\n";
    char head[320];
    std::snprintf(head, sizeof head, "  %-5s %-14s %11s %10s %9s %12s %7s %15s %8s %11s\n", "step", "G-code",
                  "extruded mm", "outside mm", "worst mm", "unsupp. mm", "unsup%", "gap/layer mm", "retract",
                  "turn clr mm");
    out << head;
    for (const slicing::StepAudit& s : program.steps) printRow(out, std::to_string(s.step), s);
    printRow(out, "all", program.total);
    for (const slicing::StepAudit& s : program.steps)
      if (!s.retractLines.empty()) {
        out << "    step " << s.step << ": extrusion while retracted at " << s.file << " line";
        for (std::size_t i = 0; i < s.retractLines.size(); ++i) out << (i ? ", " : " ") << s.retractLines[i];
        out << (s.retractViolations > static_cast<int>(s.retractLines.size()) ? ", ..." : "") << "\n";
      }
    if (!program.total.unsupportedByFeatureMm.empty()) {
      std::vector<std::pair<double, std::string>> features;
      for (const auto& [feature, mm] : program.total.unsupportedByFeatureMm) features.emplace_back(mm, feature);
      std::sort(features.rbegin(), features.rend());
      out << "    unsupported by feature:";
      for (std::size_t i = 0; i < features.size(); ++i)
        out << (i ? ", " : " ") << features[i].second << " " << number(features[i].first, 1) << " mm";
      out << "\n";
    }
    printPlaces(out, "outside the region and supports (a), worst places", program.outsidePlaces, true);
    printPlaces(out, "unsupported (b), worst places", program.unsupportedPlaces, false);
  }
  if (!report.findings.empty()) {
    out << "\nFindings:\n";
    for (const std::string& f : report.findings) out << "  " << f << "\n";
  }
}

// Why the audit fails, one phrase per check, summed over the programs.
std::vector<std::string> failureReasons(const slicing::AuditReport& report, bool strict) {
  double outside = 0.0, unsupported = 0.0;
  int firstLayers = 0, retracts = 0, turns = 0;
  for (const slicing::ProgramAudit& p : report.programs) {
    outside += p.total.outsideMm;
    unsupported += p.total.unsupportedMm;
    retracts += p.total.retractViolations;
    for (const slicing::StepAudit& s : p.steps) {
      firstLayers += s.firstLayerViolation ? 1 : 0;
      turns += s.turnViolation ? 1 : 0;
    }
  }
  std::vector<std::string> reasons;
  if (outside > 0.0) reasons.push_back("(a) " + number(outside, 2) + " mm outside the region and supports");
  if (strict && unsupported > 0.0) reasons.push_back("(b) " + number(unsupported, 1) + " mm unsupported");
  if (firstLayers > 0) reasons.push_back("(c) " + std::to_string(firstLayers) + " first layers off their base");
  if (retracts > 0) reasons.push_back("(d) " + std::to_string(retracts) + " extrusions while retracted");
  if (turns > 0) reasons.push_back("(e) " + std::to_string(turns) + " turns with the nozzle too low");
  if (report.poseMismatches > 0)
    reasons.push_back(std::to_string(report.poseMismatches) + " poses that disagree with the kinematics");
  if (report.sequenceViolations > 0)
    reasons.push_back(std::to_string(report.sequenceViolations) + " moves out of sequence (see the findings)");
  return reasons;
}

Json numberJson(double value) { return std::isfinite(value) ? Json(value) : Json(); }

Json stepJson(const slicing::StepAudit& s) {
  Json j;
  j["step"] = s.step;
  j["file"] = s.file;
  j["extrusionMm"] = s.extrusionMm;
  j["skirtMm"] = s.skirtMm;
  j["outsideMm"] = s.outsideMm;
  j["worstOutsideMm"] = s.worstOutsideMm;
  j["unsupportedMm"] = s.unsupportedMm;
  j["unsupportedPercent"] = s.unsupportedPercent();
  j["unsupportedByFeatureMm"] = s.unsupportedByFeatureMm;
  j["firstLayerGapMm"] = numberJson(s.firstLayerGapMm);
  j["expectedGapMm"] = s.expectedGapMm;
  j["baseZMm"] = s.baseZMm;
  j["firstLayerViolation"] = s.firstLayerViolation;
  j["retractViolations"] = s.retractViolations;
  j["retractLines"] = s.retractLines;
  j["turnClearanceMm"] = numberJson(s.turnClearanceMm);
  j["turnNozzleZMm"] = numberJson(s.turnNozzleZMm);
  j["turnSweptTopZMm"] = numberJson(s.turnSweptTopZMm);
  j["turnLine"] = s.turnLine;
  j["turnViolation"] = s.turnViolation;
  return j;
}

Json placesJson(const std::vector<slicing::AuditPlace>& places) {
  Json list = Json::array();
  for (const slicing::AuditPlace& p : places)
    list.push_back({{"step", p.step},
                    {"file", p.file},
                    {"line", p.line},
                    {"modelPoint", {p.modelPoint.x(), p.modelPoint.y(), p.modelPoint.z()}},
                    {"lengthMm", p.lengthMm},
                    {"worstMm", p.worstMm}});
  return list;
}

Json reportJson(const std::string& job, const slicing::AuditReport& report, bool strict) {
  Json j;
  j["schema"] = "multidir-audit";
  j["version"] = 1;
  j["job"] = job;
  j["alphaMaxDegrees"] = report.alphaMaxDegrees;
  j["passed"] = !report.failed() && !(strict && report.hasUnsupported());
  Json programs = Json::array();
  for (const slicing::ProgramAudit& p : report.programs) {
    Json program;
    program["name"] = p.name;
    program["stitched"] = p.stitched;
    Json steps = Json::array();
    for (const slicing::StepAudit& s : p.steps) steps.push_back(stepJson(s));
    program["steps"] = steps;
    program["total"] = stepJson(p.total);
    program["outsidePlaces"] = placesJson(p.outsidePlaces);
    program["unsupportedPlaces"] = placesJson(p.unsupportedPlaces);
    programs.push_back(program);
  }
  j["programs"] = programs;
  j["poseMismatches"] = report.poseMismatches;
  j["sequenceViolations"] = report.sequenceViolations;
  j["findings"] = report.findings;
  return j;
}

}  // namespace

int runAudit(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const ParsedArgs parsed = parseArgs(args, {"--json", "--alpha"}, {"--help", "--strict"}, "audit");
  if (parsed.has("--help")) {
    out << kAuditHelp;
    return kExitOk;
  }
  const std::string jobDir = onlyPositional(parsed, "audit", "job folder", "multidir audit JOB [--json OUT]");
  slicing::AuditOptions options;
  if (parsed.has("--alpha")) {
    const double alpha = parseNumber(parsed.value("--alpha", ""), "--alpha");
    if (alpha < 0.0 || alpha >= 90.0) throw UsageError(kCommand + ": --alpha must be in [0, 90) degrees");
    options.alphaMaxDegrees = alpha;
  }
  const bool strict = parsed.has("--strict");
  const core::Result<slicing::AuditJob> job = slicing::readAuditJob(jobDir);
  if (!job) throw FileError(kCommand + ": " + job.error().describe());
  core::JobContext context;
  const core::Result<slicing::AuditReport> report = slicing::auditJob(*job, options, context);
  if (!report) throw FileError(kCommand + ": " + report.error().describe());
  printReport(out, jobDir, *report);
  if (parsed.has("--json")) {
    const std::string path = parsed.value("--json", "");
    // Through core's atomic writer: a link at `path` is replaced, never written through.
    if (const core::Status written = core::writeTextFileAtomically(path, reportJson(jobDir, *report, strict).dump(2) + "\n");
        !written)
      throw FileError(kCommand + ": --json: " + written.error().describe());
  }
  const bool failed = report->failed() || (strict && report->hasUnsupported());
  const std::vector<std::string> reasons = failureReasons(*report, strict);
  out << "\nAudit " << (failed ? "FAILED:" : "passed");
  for (std::size_t i = 0; i < reasons.size(); ++i) out << (i ? "; " : " ") << reasons[i];
  if (!strict && report->hasUnsupported())
    out << (failed ? ". Unsupported" : " (unsupported")
        << " extrusion (b) is reported, not failed: --strict fails on it" << (failed ? "" : ")");
  out << "\n";
  (void)err;
  return failed ? kExitAuditFailed : kExitOk;
}

}  // namespace multidir::cli
