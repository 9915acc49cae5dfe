#include "apart_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "multidir/assembly/assembly_sheet.h"
#include "multidir/assembly/dowels.h"
#include "multidir/assembly/part_labels.h"
#include "multidir/assembly/plates.h"
#include "multidir/assembly/three_mf.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/apart/apart_plan.h"
#include "multidir/core/common/atomic_file.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/decompose.h"
#include "multidir/slicing/estimates.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/slicer_engine.h"

namespace multidir::cli {

const char* const kApartHelp =
    "Usage: multidir apart PLAN_OR_MODEL -o OUTDIR [--printer PROFILE] [options]\n"
    "\n"
    "Prints a plan on an ordinary printer: every region becomes a part laid on the bed on its cut face, parts\n"
    "that do not fit the printer are cut further, and the parts are joined by printed dowels in holes drilled\n"
    "into both faces of every joint (docs/apart.md). PLAN_OR_MODEL is a plan folder (multidir decompose; any\n"
    "machine's plan, printed apart as it is) or a model, searched first for the apart machine.\n"
    "\n"
    "Writes to OUTDIR: part-NN.stl and dowel-NN.stl (each laid cap down, in its own frame), plate-K.stl (what\n"
    "one plate of the bed holds), parts.3mf (every part and dowel placed on its plate, read back and checked),\n"
    "with --printer plate-K.gcode (PrusaSlicer, no supports) and whole.gcode (the model in one piece with the\n"
    "slicer's supports), assembly.html with its pictures in sheet/ (the parts with their numbers, the order of\n"
    "gluing, the plates and the estimates), and apart.json with every number the table shows.\n"
    "\n"
    "Options:\n"
    "  -o OUTDIR            folder for the files (created if missing; required)\n"
    "  --printer PROFILE    printer profile (.ini, or a shipped name such as marlin-220): the bed and height\n"
    "                       parts must fit, the plates, and the slicer's settings. Without it parts are not\n"
    "                       limited in size and nothing is sliced\n"
    "  --up DIRECTION       a model's up: x, y, z, -x, -y, -z or a,b,c (default: z)\n"
    "  --scheme NAME        a model's search: beam, greedy or cgreedy (default: beam)\n"
    "  --part-cost MM2      a model's search: the risky area one more part must save (default: 240)\n"
    "  --max-parts N        refuse a plan that needs more parts than this to fit the printer (default: 64)\n"
    "  --no-slice           with --printer: lay out and write the parts, but run no slicer\n"
    "  --scale FACTOR       multiply a model's coordinates by FACTOR (default: 1)\n"
    "  -h, --help           show this help\n"
    "\n"
    "Exit codes: 0 ok, 1 a file cannot be read or written or the plan cannot be printed apart, 2 usage error.\n";

namespace {

namespace fs = std::filesystem;
const std::string kCommand = "multidir apart";

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// The plan to print apart: a saved plan as it is, or the model searched for the apart machine.
core::Decomposition planFrom(const ParsedArgs& parsed, const std::string& input, double& alphaMaxDegrees,
                             std::ostream& out) {
  const bool isPlan = fs::is_directory(input) || fs::path(input).filename() == "plan.json";
  if (isPlan) {
    for (const char* option : {"--up", "--scheme", "--part-cost", "--scale"})
      if (parsed.has(option))
        throw UsageError(kCommand + ": " + option + " is for a model; a plan is printed apart as it was searched");
    core::Result<core::LoadedPlan> loaded = core::loadPlan(input);
    if (!loaded) throw FileError(kCommand + ": " + loaded.error().describe());
    alphaMaxDegrees = loaded->metadata.options.alphaMaxDegrees;
    out << "Plan " << input << " (" << core::machineKindName(loaded->metadata.machine.kind) << ", "
        << loaded->decomposition.regions.size() << " regions), printed apart as it is\n";
    return std::move(loaded->decomposition);
  }
  core::Result<core::LoadedMesh> model = core::loadMesh(input, modelLoadOptions(parsed, kCommand));
  if (!model) throw FileError(kCommand + ": " + model.error().describe());
  core::MachineSpec machine;
  machine.kind = core::MachineKind::Apart;
  if (parsed.has("--up")) {
    const core::Result<core::Vec3> up = core::parseDirection(parsed.value("--up", ""));
    if (!up) throw UsageError(kCommand + ": --up: " + up.error().message);
    machine.up = *up;
  }
  machine.rotationAxis = core::platformFrameX(machine.up);
  core::SearchOptions options;
  if (parsed.has("--scheme")) {
    const core::Result<core::SearchScheme> scheme = core::parseScheme(parsed.value("--scheme", ""));
    if (!scheme) throw UsageError(kCommand + ": --scheme: " + scheme.error().message);
    options.scheme = *scheme;
  }
  if (parsed.has("--part-cost")) options.partCostMm2 = parseNumber(parsed.value("--part-cost", ""), "--part-cost");
  if (core::Status valid = core::validate(options); !valid)
    throw UsageError(kCommand + ": " + valid.error().message);
  alphaMaxDegrees = options.alphaMaxDegrees;
  out << "Searching " << input << " for the apart machine (" << core::schemeName(options.scheme) << ", part cost "
      << fixed(options.partCostMm2, 0) << " mm^2)\n";
  core::JobContext job;
  core::Result<core::Decomposition> plan = core::decompose(model->mesh, machine, options, job);
  if (!plan) throw FileError(kCommand + ": " + plan.error().describe());
  out << "J_G before " << fixed(plan->jgBeforeMm2, 2) << " mm^2 (one piece along up), after " << fixed(plan->jgAfterMm2, 2)
      << " mm^2 with " << plan->regions.size() << " regions\n";
  return std::move(*plan);
}

void save(const core::TriangleMesh& mesh, const fs::path& path) {
  if (core::Status s = core::saveMesh(mesh, path.string()); !s) throw FileError(kCommand + ": " + s.error().describe());
}

// A mesh moved so its box corner is at the origin (what a slicer shows when it opens the file).
core::TriangleMesh atOrigin(core::TriangleMesh mesh) {
  const core::BoundingBox box = core::boundingBox(mesh);
  for (core::Vec3& v : mesh.vertices) v -= box.min;
  return mesh;
}

struct Sliced {
  slicing::Estimate estimate;
  bool ok = false;
};

Sliced sliceMesh(const core::TriangleMesh& mesh, const slicing::PrinterProfile& profile, const fs::path& folder,
                 const std::string& stem, const std::vector<std::pair<std::string, std::string>>& overlay) {
  const fs::path meshPath = folder / (stem + ".stl"), iniPath = folder / (stem + ".ini"),
                 gcodePath = folder / (stem + ".gcode");
  save(mesh, meshPath);
  std::string ini;
  for (const auto& [key, value] : overlay) ini += key + " = " + value + "\n";
  if (core::Status s = core::writeTextFileAtomically(iniPath.string(), ini); !s)
    throw FileError(kCommand + ": " + s.error().describe());
  slicing::SliceRequest request;
  request.meshFile = meshPath.string();
  request.configFiles = {profile.path, iniPath.string()};
  request.outputFile = gcodePath.string();
  core::JobContext job;
  const core::Result<slicing::SliceRun> run = slicing::PrusaSlicerEngine().slice(request, job);
  fs::remove(iniPath);
  if (!run) throw FileError(kCommand + ": " + run.error().describe());
  const core::Result<slicing::Estimate> estimate = slicing::parseEstimate(run->gcode, gcodePath.filename().string());
  if (!estimate) throw FileError(kCommand + ": " + estimate.error().describe());
  return {*estimate, true};
}

}  // namespace

int runApart(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  (void)err;
  const ParsedArgs parsed = parseArgs(args, {"-o", "--printer", "--up", "--scheme", "--part-cost", "--max-parts", "--scale"},
                                      {"--help", "--no-slice"}, "apart");
  if (parsed.has("--help")) {
    out << kApartHelp;
    return kExitOk;
  }
  const std::string input = onlyPositional(parsed, kCommand, "plan or model", "multidir apart PLAN_OR_MODEL -o OUTDIR");
  const fs::path folder = outputFolder(parsed, kCommand, "the parts, dowels, plates and 3MF");
  checkOutputFolder(folder.string(), kCommand);
  if (parsed.has("--no-slice") && !parsed.has("--printer"))
    throw UsageError(kCommand + ": --no-slice goes with --printer (without a printer nothing is sliced)");

  std::optional<slicing::PrinterProfile> profile;
  if (parsed.has("--printer")) {
    core::Result<slicing::PrinterProfile> loaded = slicing::loadPrinterProfile(parsed.value("--printer", ""));
    if (!loaded) throw FileError(kCommand + ": --printer: " + loaded.error().describe());
    profile = std::move(*loaded);
  }
  core::ApartOptions apartOptions;
  if (parsed.has("--max-parts")) {
    const double n = parseNumber(parsed.value("--max-parts", ""), "--max-parts");
    if (n != std::floor(n) || n < 1 || n > 1000) throw UsageError(kCommand + ": --max-parts expects 1 to 1000");
    apartOptions.maxParts = static_cast<int>(n);
  }
  assembly::PlateOptions plates;
  if (profile) {
    plates.bedMin = profile->bedMin();
    plates.bedMax = profile->bedMax();
    plates.maxHeightMm = profile->maxPrintHeightMm;
    const Eigen::Vector2d room = plates.bedMax - plates.bedMin - Eigen::Vector2d::Constant(2.0 * plates.marginMm);
    apartOptions.buildVolume = {room.x(), room.y(), plates.maxHeightMm};
  }

  double alpha = core::kDefaultAlphaMaxDegrees;
  const core::Decomposition plan = planFrom(parsed, input, alpha, out);
  apartOptions.alphaMaxDegrees = alpha;
  const core::Result<core::ApartPlan> apart = core::apartPlan(plan, apartOptions);
  if (!apart) throw FileError(kCommand + ": " + apart.error().describe());
  const assembly::DowelOptions dowelOptions;
  const assembly::DowelLayout layout = assembly::placeDowels(*apart, dowelOptions);
  const core::Result<assembly::DrilledParts> drilled = assembly::drillParts(*apart, layout, dowelOptions);
  if (!drilled) throw FileError(kCommand + ": " + drilled.error().describe());
  // Each part's number sunk into a joint face that gluing hides, where there is room.
  const assembly::LabelOptions labelOptions;
  const std::vector<assembly::PartLabel> labels = assembly::placeLabels(*apart, layout, dowelOptions, labelOptions);
  const core::Result<std::vector<core::TriangleMesh>> numbered =
      assembly::debossLabels(drilled->parts, labels, labelOptions);
  if (!numbered) throw FileError(kCommand + ": " + numbered.error().describe());

  std::vector<core::Vec3> directions, axes;
  for (const core::ApartPart& part : apart->parts) directions.push_back(part.printingDirection);
  for (const assembly::Dowel& dowel : layout.dowels) axes.push_back(dowel.axis);
  if (!profile) {
    // No printer: one plate as large as the largest part needs (nothing is limited, nothing sliced).
    plates.bedMax = Eigen::Vector2d::Constant(1e6);
    plates.maxHeightMm = 1e6;
  }
  const core::Result<assembly::PlateLayout> arranged =
      assembly::arrangeOnPlates(*numbered, directions, drilled->dowels, axes, plates);
  if (!arranged) throw FileError(kCommand + ": " + arranged.error().describe());

  fs::create_directories(folder);
  for (const assembly::PlateItem& item : arranged->items) save(atOrigin(item.mesh), folder / (item.name + ".stl"));
  const fs::path threeMf = folder / "parts.3mf";
  if (core::Status s = assembly::write3mf(*arranged, plates, threeMf.string()); !s)
    throw FileError(kCommand + ": " + s.error().describe());
  // Read back: the same items, meshes and placements, else the file is not what was meant.
  const core::Result<std::vector<assembly::ThreeMfItem>> readBack = assembly::read3mf(threeMf.string());
  if (!readBack) throw FileError(kCommand + ": " + readBack.error().describe());
  const std::vector<assembly::ThreeMfItem> written = assembly::threeMfItems(*arranged, plates);
  bool same = readBack->size() == written.size();
  for (std::size_t i = 0; same && i < written.size(); ++i)
    same = (*readBack)[i].name == written[i].name && (*readBack)[i].triangles == written[i].triangles &&
           ((*readBack)[i].transform - written[i].transform).cwiseAbs().maxCoeff() < 1e-3;
  if (!same) throw FileError(kCommand + ": " + threeMf.string() + " does not read back as written (lib3mf)");

  out << "Parts " << apart->parts.size() << " (" << apart->cutsToFit << " cut further to fit), joints "
      << apart->joints.size() << ", dowels " << layout.dowels.size() << ", plates " << arranged->plates << "\n";
  out << "J_G apart " << fixed(apart->jgMm2, 2) << " mm^2 (the bed under every part; the plan: "
      << fixed(plan.jgAfterMm2, 2) << " mm^2)\n";
  for (const assembly::JointDowels& joint : layout.joints)
    if (!joint.note.empty()) out << "Joint " << joint.joint + 1 << ": " << joint.note << "\n";
  int unnumbered = 0;
  nlohmann::ordered_json labelRecords = nlohmann::ordered_json::array();
  for (const assembly::PartLabel& label : labels) {
    if (!label.placed) {
      ++unnumbered;
      out << "Part " << label.part + 1 << ": " << label.note << "\n";
    }
    nlohmann::ordered_json record = {{"part", label.part + 1}, {"number", label.text}, {"placed", label.placed}};
    if (label.placed) {
      record["joint"] = label.joint + 1;
      record["heightMm"] = label.heightMm;
    } else {
      record["note"] = label.note;
    }
    labelRecords.push_back(record);
  }

  nlohmann::ordered_json summary = {{"parts", apart->parts.size()},
                                    {"cutsToFit", apart->cutsToFit},
                                    {"joints", apart->joints.size()},
                                    {"dowels", layout.dowels.size()},
                                    {"plates", arranged->plates},
                                    {"jgApartMm2", apart->jgMm2},
                                    {"jgPlanMm2", plan.jgAfterMm2},
                                    {"jgBeforeMm2", plan.jgBeforeMm2},
                                    {"partsNumbered", static_cast<int>(labels.size()) - unnumbered},
                                    {"labels", labelRecords}};
  if (profile) {
    for (int p = 0; p < arranged->plates; ++p) save(assembly::plateMesh(*arranged, p), folder / ("plate-" + std::to_string(p + 1) + ".stl"));
  }
  std::vector<assembly::SheetEstimate> sheetEstimates;
  if (profile && !parsed.has("--no-slice")) {
    out << "Plate   time          filament cm^3\n";
    slicing::Estimate total;
    nlohmann::ordered_json perPlate = nlohmann::ordered_json::array();
    for (int p = 0; p < arranged->plates; ++p) {
      const Sliced s = sliceMesh(assembly::plateMesh(*arranged, p), *profile, folder, "plate-" + std::to_string(p + 1),
                                 {{"support_material", "0"}});
      total += s.estimate;
      out << std::setw(5) << p + 1 << "   " << std::setw(12) << slicing::durationText(s.estimate.printSeconds) << "  "
          << fixed(s.estimate.filamentCm3, 2) << "\n";
      perPlate.push_back({{"plate", p + 1},
                          {"seconds", s.estimate.printSeconds},
                          {"filamentCm3", s.estimate.filamentCm3},
                          {"supportCm3", s.estimate.supportCm3}});
      sheetEstimates.push_back({"Plate " + std::to_string(p + 1), s.estimate.printSeconds, s.estimate.filamentCm3,
                                s.estimate.supportCm3});
    }
    // The whole model in one piece along up, centred on the bed, with the slicer's supports.
    core::TriangleMesh whole;
    for (const core::Region& region : plan.regions) {
      const auto base = static_cast<std::int32_t>(whole.vertices.size());
      whole.vertices.insert(whole.vertices.end(), region.mesh.vertices.begin(), region.mesh.vertices.end());
      for (const core::Triangle& t : region.mesh.triangles) whole.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    whole.resetOrigins();
    const core::Vec3 up = plan.regions.front().printingDirection;
    const Eigen::Matrix3d toUp = Eigen::Quaterniond::FromTwoVectors(up, core::Vec3::UnitZ()).toRotationMatrix();
    for (core::Vec3& v : whole.vertices) v = toUp * v;
    const core::BoundingBox box = core::boundingBox(whole);
    const Eigen::Vector2d centre = 0.5 * (plates.bedMin + plates.bedMax);
    const core::Vec3 shift(centre.x() - 0.5 * (box.min.x() + box.max.x()), centre.y() - 0.5 * (box.min.y() + box.max.y()), -box.min.z());
    for (core::Vec3& v : whole.vertices) v += shift;
    const Sliced one = sliceMesh(whole, *profile, folder, "whole", {{"support_material", "1"},
                                                                   {"support_material_auto", "1"},
                                                                   {"support_material_threshold", fixed(alpha, 0)}});
    out << "Total   " << std::setw(12) << slicing::durationText(total.printSeconds) << "  " << fixed(total.filamentCm3, 2)
        << "\n";
    out << "One piece with supports " << slicing::durationText(one.estimate.printSeconds) << "  "
        << fixed(one.estimate.filamentCm3, 2) << " cm^3, of which support " << fixed(one.estimate.supportCm3, 2)
        << " cm^3\n";
    sheetEstimates.push_back({"All plates", total.printSeconds, total.filamentCm3, total.supportCm3});
    sheetEstimates.push_back({"One piece with supports", one.estimate.printSeconds, one.estimate.filamentCm3,
                              one.estimate.supportCm3});
    summary["platesSliced"] = perPlate;
    summary["apartSeconds"] = total.printSeconds;
    summary["apartFilamentCm3"] = total.filamentCm3;
    summary["apartSupportCm3"] = total.supportCm3;
    summary["wholeSupportCm3"] = one.estimate.supportCm3;
    summary["wholeSeconds"] = one.estimate.printSeconds;
    summary["wholeFilamentCm3"] = one.estimate.filamentCm3;
  }
  // The assembly sheet: parts, gluing order, plates and estimates, with its pictures in sheet/.
  assembly::SheetInput sheetInput;
  sheetInput.title = "Assembly of " + fs::path(input).filename().string();
  sheetInput.plan = &*apart;
  sheetInput.layout = &layout;
  sheetInput.dowelOptions = dowelOptions;
  sheetInput.labels = &labels;
  sheetInput.parts = &*numbered;
  sheetInput.dowels = &drilled->dowels;
  sheetInput.plates = &*arranged;
  sheetInput.estimates = sheetEstimates;
  const core::Result<assembly::Sheet> sheet = assembly::assemblySheet(sheetInput);
  if (!sheet) throw FileError(kCommand + ": " + sheet.error().describe());
  fs::create_directories(folder / "sheet");
  for (const assembly::SheetPicture& picture : sheet->pictures)
    if (core::Status s = core::writeTextFileAtomically((folder / picture.name).string(),
                                                       std::string(picture.png.begin(), picture.png.end()));
        !s)
      throw FileError(kCommand + ": " + s.error().describe());
  if (core::Status s = core::writeTextFileAtomically((folder / "assembly.html").string(), sheet->html); !s)
    throw FileError(kCommand + ": " + s.error().describe());
  if (core::Status s = core::writeTextFileAtomically((folder / "apart.json").string(), summary.dump(2) + "\n"); !s)
    throw FileError(kCommand + ": " + s.error().describe());
  out << "Written to " << folder.string() << "\n";
  return kExitOk;
}

}  // namespace multidir::cli
