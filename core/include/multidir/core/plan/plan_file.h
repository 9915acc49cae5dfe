#pragma once
// Plan files: a decomposition on disk, as a folder with plan.json and one binary STL per region, and
// machine profiles (one JSON file per machine). The format is versioned and documented in
// docs/plan-format.md; these functions are the only code that reads or writes it.
//
// Folder layout written by savePlan:
//   plan.json        schema "multidir-plan", version kPlanFormatVersion: metadata, planes, regions
//   region-01.stl    the first region in printing order (binary STL, mm), region-02.stl, ...
//   region-01-supports.stl   optional: the supports printed with region 1 (binary STL, mm), ...
#include <optional>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/search/machine.h"
#include "multidir/core/search/search_options.h"
#include "multidir/core/supports/support_set.h"

namespace multidir::core {

constexpr int kPlanFormatVersion = 1;
constexpr int kMachineProfileVersion = 1;

// A pose tried by the pose search (decomposeWithPoseSearch), as plan.json records it.
struct PlanPoseTrial {
  Vec3 up = Vec3::UnitZ();   // unit, in the model's coordinates
  std::string source;        // "given" or "resting" ("sampled" in plans of older versions)
  double jgAfterMm2 = 0.0;   // full search, or the cheap (greedy) plan's when not fully searched
  int regions = 0;
  bool searched = false;
  double contactAreaMm2 = 0.0;     // the hull patch it stands on (docs/search.md, "The pose search")
  double stabilityMarginMm = 0.0;  // the centre of mass's projection inside that patch (> 0)
};

// The pose the search chose: its up, and the rotation that turns the input model so that this up points
// along the up it was given (the platform's up). Plans stay in the model's coordinates.
struct PlanPose {
  Vec3 up = Vec3::UnitZ();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  std::string source;
  double contactAreaMm2 = 0.0;     // the hull patch it stands on
  double stabilityMarginMm = 0.0;  // the centre of mass's projection inside that patch (0 in older plans)
  std::vector<PlanPoseTrial> runnersUp;  // the other poses tried, best J_G first
};

// What a plan was computed from, stored beside it so a plan can be checked against its model and rerun.
struct PlanMetadata {
  std::string modelPath;        // as the user gave it
  std::string modelChecksum;    // checksumText() of the model file's bytes (see plan/checksum.h)
  Vec3 up = Vec3::UnitZ();      // unit; the model's up direction as given
  MachineSpec machine;          // every field, as the search used it (4-DOF: before any axis search)
  SearchOptions options;        // every field
  int axisSearchCount = 0;      // 4-DOF axes tried by decomposeWithAxisSearch; 0: no axis search
  std::optional<PlanPose> pose; // set when the pose search chose machine.up (--pose auto)
  std::string multidirVersion;  // the MultiDir that wrote the plan ("0.1.0")
};

struct LoadedPlan {
  PlanMetadata metadata;
  Decomposition decomposition;  // region meshes from the STLs (float precision), origins restored
  std::string directory;        // the plan's folder
  // One per region in printing order (empty sets where a region has none); meshes rebuilt from the skeletons
  // in plan.json at double precision.
  std::vector<SupportSet> supports;
  int formatVersion = kPlanFormatVersion;
};

// Writes plan.json and region-NN.stl (NN from 01, at least two digits) into `directory`, creating it and
// its parents if missing. Region files are written first and plan.json last, each beside its target and
// renamed into place, so a folder whose plan.json exists holds a complete plan. Files of an older plan with
// more regions are left alone (plan.json names the files that belong to it).
// Binary STL holds float corners: corners closer than float can tell apart (clipping leaves some a few
// nanometres apart) become one, and the sliver faces this collapses are left out of both the STL and the
// stored face origins, so a loaded plan's faces and origins line up one for one.
// Errors: InvalidParameter (the decomposition or metadata is inconsistent: the message names the field),
// WriteFailed (the folder cannot be created or a file written; the message says which and why).
Status savePlan(const Decomposition& plan, const PlanMetadata& metadata, const std::string& directory);

// The same with supports: `supports` is empty (no supports) or holds one set per region in printing order.
// A region with a non-empty set gets a `supports` field in plan.json (its skeleton and totals) and
// region-NN-supports.stl (its solids), written before plan.json. Errors: as above; InvalidParameter when the
// number of sets differs from the number of regions or a set's regionIndex is not its position.
Status savePlan(const Decomposition& plan, const PlanMetadata& metadata, const std::vector<SupportSet>& supports,
                const std::string& directory);

// Reads a plan written by savePlan: give its folder or its plan.json. Every field is checked (schema and
// version, types, ranges, unit vectors, counts, the region files and their triangle counts) and the first
// violation is returned, naming the file and the field: "plan.json: regions[2].printingDirection is not a
// unit vector". Unknown fields are ignored, so later minor additions stay readable.
// Errors: FileNotFound (plan.json or a region file missing), MalformedFile (invalid JSON or field),
// InvalidParameter (a machine or search setting out of range), TooLarge, plus the region STLs' load errors
// with the file named. Region meshes come back at float precision (binary STL); volumes and risky areas are
// the stored values, not recomputed. Support STLs must exist and hold as many triangles as plan.json says;
// the support meshes themselves are rebuilt from the skeletons stored in plan.json.
Result<LoadedPlan> loadPlan(const std::string& directoryOrPlanJson);

// A machine as a JSON file (schema "multidir-machine", version kMachineProfileVersion; docs/plan-format.md).
// saveMachineProfile refuses an invalid spec (validate(MachineSpec)) with InvalidParameter; WriteFailed.
Status saveMachineProfile(const MachineSpec& machine, const std::string& path);

// Reads and checks a machine profile: every field's type, then validate(MachineSpec).
// Errors: FileNotFound, MalformedFile (naming the field), InvalidParameter (a value out of range).
Result<MachineSpec> loadMachineProfile(const std::string& path);

// The same checks on a profile already in memory (JSON text): no file is written or read. `name` names it in
// errors ("print-job.json: machine"). Errors: MalformedFile (naming the field), InvalidParameter.
Result<MachineSpec> parseMachineProfile(const std::string& jsonText, const std::string& name);

}  // namespace multidir::core
