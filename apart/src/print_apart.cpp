#include "multidir/apart/print_apart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "apart_files.h"
#include "multidir/assembly/assembly_sheet.h"
#include "multidir/assembly/three_mf.h"
#include "multidir/core/common/atomic_file.h"
#include "multidir/core/common/staged_folder.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/slicing/slicer_engine.h"

namespace multidir::apart {

namespace {

namespace fs = std::filesystem;
using core::Error;
using core::ErrorCode;

// The share of the run's progress each stage ends at. Slicing takes most of the time when it runs (minutes per
// plate against seconds for the rest), so it gets most of the bar.
constexpr double kPlanned = 0.04, kDowelsPlaced = 0.08, kDrilled = 0.2, kNumbered = 0.26, kPlatesLaid = 0.3,
                 kFilesWritten = 0.34, kSliced = 0.95;

Error cancelled(const std::string& stage) {
  return Error{ErrorCode::Cancelled, "printing apart was cancelled before " + stage + "; nothing was written", "apart"};
}

// A mesh moved so its box corner is at the origin (what a slicer shows when it opens the file).
core::TriangleMesh atOrigin(core::TriangleMesh mesh) {
  const core::BoundingBox box = core::boundingBox(mesh);
  for (core::Vec3& v : mesh.vertices) v -= box.min;
  return mesh;
}

// The whole model in one piece along up (the first region's printing direction), centred on the bed.
core::TriangleMesh onePiece(const core::Decomposition& plan, const assembly::PlateOptions& plates) {
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
  const core::Vec3 shift(centre.x() - 0.5 * (box.min.x() + box.max.x()), centre.y() - 0.5 * (box.min.y() + box.max.y()),
                         -box.min.z());
  for (core::Vec3& v : whole.vertices) v += shift;
  return whole;
}

class Writer {
 public:
  Writer(std::string folder, std::vector<std::string>& files) : m_folder(std::move(folder)), m_files(files) {}
  std::string path(const std::string& name) const { return (fs::path(m_folder) / name).string(); }
  core::Status mesh(const core::TriangleMesh& mesh, const std::string& name) {
    if (core::Status s = core::saveMesh(mesh, path(name)); !s) return s.error();
    m_files.push_back(name);
    return core::Done{};
  }
  void wrote(const std::string& name) { m_files.push_back(name); }

 private:
  std::string m_folder;
  std::vector<std::string>& m_files;
};

// Slices `mesh` (saved as STEM.stl) with the printer's settings and `overlay` over them into STEM.gcode. The
// overlay goes in a temporary STEM.ini beside them, removed afterwards. Progress of the slicer mapped onto
// [from, to] of the job's.
core::Result<slicing::Estimate> sliceMesh(const core::TriangleMesh& mesh, const slicing::PrinterProfile& printer,
                                          Writer& writer, const std::string& stem,
                                          const std::vector<std::pair<std::string, std::string>>& overlay,
                                          core::JobContext& job, double from, double to, const std::string& phase) {
  job.setProgress(from, phase);
  if (core::Status s = writer.mesh(mesh, stem + ".stl"); !s) return s.error();
  std::string ini;
  for (const auto& [key, value] : overlay) ini += key + " = " + value + "\n";
  const std::string iniPath = writer.path(stem + ".ini");
  if (core::Status s = core::writeTextFileAtomically(iniPath, ini); !s) return s.error();
  slicing::SliceRequest request;
  request.meshFile = writer.path(stem + ".stl");
  request.configFiles = {printer.path, iniPath};
  request.outputFile = writer.path(stem + ".gcode");
  request.heightMm = core::boundingBox(mesh).max.z() - core::boundingBox(mesh).min.z();
  request.progress = [&job, from, to, phase](double f) { job.setProgress(from + f * (to - from), phase); };
  const core::Result<slicing::SliceRun> run = slicing::PrusaSlicerEngine().slice(request, job);
  std::error_code ignored;
  fs::remove(iniPath, ignored);
  if (!run) return run.error();
  writer.wrote(stem + ".gcode");
  return slicing::parseEstimate(run->gcode, stem + ".gcode");
}

// The slicer's supports as the one-piece comparison has them: on, automatic, at the plan's overhang angle. A
// part without risky area gets none; a part that still has some gets what the slicer gives it, so the plates'
// support is the slicer's own number (docs/apart.md, "Support volume").
std::vector<std::pair<std::string, std::string>> withSupports(double alphaMaxDegrees) {
  return {{"support_material", "1"},
          {"support_material_auto", "1"},
          {"support_material_threshold", std::to_string(slicerSupportThreshold(alphaMaxDegrees))}};
}

}  // namespace

int slicerSupportThreshold(double alphaMaxDegrees) {
  // PrusaSlicer 2.5 supports a face whose slope from the horizontal is below the threshold + 1 degree ("+1
  // makes the threshold inclusive", SupportMaterial.cpp); the threshold is a whole number and 0 means its
  // own automatic rule. A face is risky when its normal is less than alpha from straight down, which is its
  // slope (docs/apart.md, "Where the slicer puts support").
  return std::max(1, static_cast<int>(std::floor(alphaMaxDegrees)) - 1);
}

assembly::PlateOptions plateOptionsFor(const std::optional<slicing::PrinterProfile>& printer) {
  assembly::PlateOptions plates;
  if (printer) {
    plates.bedMin = printer->bedMin();
    plates.bedMax = printer->bedMax();
    plates.maxHeightMm = printer->maxPrintHeightMm;
  } else {
    // No printer: one plate as large as the largest part needs (nothing is limited, nothing sliced).
    plates.bedMax = Eigen::Vector2d::Constant(1e6);
    plates.maxHeightMm = 1e6;
  }
  return plates;
}

core::Result<ApartResult> printApart(const core::Decomposition& plan, const PrintApartOptions& options,
                                     const std::string& folder, core::JobContext& job) {
  if (plan.regions.empty()) return Error{ErrorCode::InvalidParameter, "the plan has no regions: search the model first", "apart"};
  ApartResult result;
  result.jgPlanMm2 = plan.jgAfterMm2;
  result.jgBeforeMm2 = plan.jgBeforeMm2;
  result.plateOptions = plateOptionsFor(options.printer);
  core::ApartOptions apartOptions;
  apartOptions.maxParts = options.maxParts;
  apartOptions.alphaMaxDegrees = options.alphaMaxDegrees;
  if (options.printer) {
    const assembly::PlateOptions& p = result.plateOptions;
    const Eigen::Vector2d room = p.bedMax - p.bedMin - Eigen::Vector2d::Constant(2.0 * p.marginMm);
    apartOptions.buildVolume = {room.x(), room.y(), p.maxHeightMm};
  }

  job.setProgress(0.0, "plan: the parts, cut to fit the printer");
  core::Result<core::ApartPlan> parts = core::apartPlan(plan, apartOptions);
  if (!parts) return parts.error();
  result.plan = std::move(*parts);
  if (job.isCancelled()) return cancelled("the dowels");

  job.setProgress(kPlanned, "dowels: placing them on every joint");
  result.layout = assembly::placeDowels(result.plan, options.dowels);
  if (job.isCancelled()) return cancelled("drilling");

  job.setProgress(kDowelsPlaced, "drilling the dowel holes");
  core::Result<assembly::DrilledParts> drilled = assembly::drillParts(result.plan, result.layout, options.dowels);
  if (!drilled) return drilled.error();
  result.dowels = std::move(drilled->dowels);
  if (job.isCancelled()) return cancelled("the part numbers");

  // Each part's number sunk into a joint face that gluing hides, where there is room.
  job.setProgress(kDrilled, "numbers: sinking each part's number into a joint face");
  result.labels = assembly::placeLabels(result.plan, result.layout, options.dowels, options.labels);
  core::Result<std::vector<core::TriangleMesh>> numbered =
      assembly::debossLabels(drilled->parts, result.labels, options.labels);
  if (!numbered) return numbered.error();
  result.parts = std::move(*numbered);
  if (job.isCancelled()) return cancelled("the plates");

  job.setProgress(kNumbered, "plates: laying the parts on the bed");
  std::vector<core::Vec3> directions, axes;
  for (const core::ApartPart& part : result.plan.parts) directions.push_back(part.printingDirection);
  for (const assembly::Dowel& dowel : result.layout.dowels) axes.push_back(dowel.axis);
  core::Result<assembly::PlateLayout> arranged =
      assembly::arrangeOnPlates(result.parts, directions, result.dowels, axes, result.plateOptions);
  if (!arranged) return arranged.error();
  result.plates = std::move(*arranged);
  if (job.isCancelled()) return cancelled("writing the files");

  // Everything is written into a staged folder beside `folder`, which takes its place only when complete.
  const fs::path target = fs::absolute(fs::path(folder)).lexically_normal();
  std::error_code ec;
  fs::create_directories(target.parent_path(), ec);
  core::Result<core::StagedFolder> staged = core::StagedFolder::beside(target.string());
  if (!staged) return staged.error();
  Writer writer(staged->path(), result.files);

  job.setProgress(kPlatesLaid, "3MF: writing the parts");
  for (const assembly::PlateItem& item : result.plates.items)
    if (core::Status s = writer.mesh(atOrigin(item.mesh), item.name + ".stl"); !s) return s.error();
  if (core::Status s = assembly::write3mf(result.plates, result.plateOptions, writer.path("parts.3mf")); !s)
    return s.error();
  writer.wrote("parts.3mf");
  // Read back: the same items, meshes and placements, else the file is not what was meant.
  const core::Result<std::vector<assembly::ThreeMfItem>> readBack = assembly::read3mf(writer.path("parts.3mf"));
  if (!readBack) return readBack.error();
  const std::vector<assembly::ThreeMfItem> written = assembly::threeMfItems(result.plates, result.plateOptions);
  bool same = readBack->size() == written.size();
  for (std::size_t i = 0; same && i < written.size(); ++i)
    same = (*readBack)[i].name == written[i].name && (*readBack)[i].triangles == written[i].triangles &&
           ((*readBack)[i].transform - written[i].transform).cwiseAbs().maxCoeff() < 1e-3;
  if (!same)
    return Error{ErrorCode::Internal, "parts.3mf does not read back as written (lib3mf)", (target / "parts.3mf").string()};
  if (job.isCancelled()) return cancelled("slicing");

  job.setProgress(kFilesWritten, "plates: writing them");
  const bool slice = options.printer && options.slice;
  if (options.printer && !slice)
    for (int p = 0; p < result.plates.plates; ++p)
      if (core::Status s = writer.mesh(assembly::plateMesh(result.plates, p), "plate-" + std::to_string(p + 1) + ".stl"); !s)
        return s.error();
  if (slice) {
    // Each plate a share of the slicing, the one piece (the largest job) as much as two plates.
    const double share = (kSliced - kFilesWritten) / (result.plates.plates + 2.0);
    for (int p = 0; p < result.plates.plates; ++p) {
      if (job.isCancelled()) return cancelled("slicing plate " + std::to_string(p + 1));
      const std::string phase = "slicing plate " + std::to_string(p + 1) + " of " + std::to_string(result.plates.plates);
      core::Result<slicing::Estimate> estimate =
          sliceMesh(assembly::plateMesh(result.plates, p), *options.printer, writer, "plate-" + std::to_string(p + 1),
                    withSupports(options.alphaMaxDegrees), job, kFilesWritten + p * share,
                    kFilesWritten + (p + 1) * share, phase);
      if (!estimate) return estimate.error();
      result.plateEstimates.push_back({p, *estimate});
      result.total += *estimate;
    }
    if (job.isCancelled()) return cancelled("slicing the model in one piece");
    // The whole model in one piece along up, centred on the bed, with the slicer's supports.
    core::Result<slicing::Estimate> whole =
        sliceMesh(onePiece(plan, result.plateOptions), *options.printer, writer, "whole",
                  withSupports(options.alphaMaxDegrees), job, kFilesWritten + result.plates.plates * share, kSliced,
                  "slicing the model in one piece with supports");
    if (!whole) return whole.error();
    result.whole = *whole;
    result.sliced = true;
  }
  if (job.isCancelled()) return cancelled("the assembly sheet");

  job.setProgress(kSliced, "assembly sheet: drawing its pictures");
  if (core::Status s = writeSheetAndSummary(result, options, staged->path()); !s) return s.error();
  if (job.isCancelled()) return cancelled("putting the files in place");
  if (core::Status s = commitFolder(*staged); !s) return s.error();
  result.folder = target.string();
  job.setProgress(1.0, "written");
  return result;
}

}  // namespace multidir::apart
