#pragma once
// MultiDir Studio projects: one JSON file (`.multidir`, schema "multidir-project", docs/plan-format.md) that
// names the model and keeps the settings and the plan's clipping planes. Region meshes are not stored: a
// reopened project rebuilds its plan from the planes (rebuildProjectPlan), and the J_G saved beside them tells
// whether the rebuilt plan is the one that was saved.
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/geometry/plane.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/search/machine.h"
#include "multidir/core/search/search_options.h"

namespace multidir::core {

constexpr int kProjectFormatVersion = 1;
// The extension project files carry (the studio recognises projects by it).
constexpr const char* kProjectFileExtension = ".multidir";
// More clipping planes than this are refused: the search never makes more than a few dozen.
constexpr std::size_t kMaxProjectPlanes = 10000;

// How a pose search chose the model's up (the studio's "Find best pose"): kept so that a reopened project
// says so and an exported plan records the pose. Absent when the user chose the up.
struct ProjectPose {
  std::string source;               // "given", "resting" or "sampled" (poseSourceName)
  double contactAreaMm2 = 0.0;      // resting: area of the hull patch the model rests on; else 0
  Vec3 platformUp = Vec3::UnitZ();  // unit; the up the search started from (poseRotation(up, platformUp) turns the model)
};

// The model a project is about: a mesh file, or a generated sample (which has no file). Exactly one of `path`
// and `sampleId` is set.
struct ProjectModel {
  // The mesh file. saveProject stores it relative to the project file's folder when it lies below that
  // folder (so a project and its model can move together), else absolute; loadProject returns it absolute.
  std::string path;
  std::string checksum;     // checksumText() of the file's bytes when the project was saved; empty: unknown
  std::string sampleId;     // a core::samples id
  Vec3 up = Vec3::UnitZ();  // unit; the direction the model is printed along
  std::optional<ProjectPose> pose;  // set when a pose search chose `up`
};

// A plan, as the clipping planes that make it plus what they were computed with.
struct ProjectPlan {
  MachineSpec machine;                // as the search used it (4-DOF: before any axis search turned its axis)
  SearchOptions options;              // as the search used them
  int axisSearchCount = 0;            // 4-DOF axes the search tried; 0: the machine's own axis only
  Vec3 rotationAxis = Vec3::UnitX();  // Decomposition::rotationAxis: 4-DOF, the axis the plan is printed about
  std::vector<Plane> clippingPlanes;  // in clipping order (plane k cut region N-k off), unit normals
  double jgBeforeMm2 = 0.0;           // as the plan reported them when it was saved
  double jgAfterMm2 = 0.0;
  bool cancelled = false;  // the search was stopped early and this was its best plan so far
};

struct Project {
  ProjectModel model;
  MachineSpec machine;              // the settings for the next search (every field)
  SearchOptions options;            // every field
  int axisSearchCount = 0;          // 0 to 3600
  std::optional<ProjectPlan> plan;  // none: no plan was shown
  std::string multidirVersion;      // the MultiDir that wrote the file ("0.1.0")
};

// What a project keeps of `plan`, computed with `machine`, `options` and `axisSearchCount`.
ProjectPlan projectPlanOf(const Decomposition& plan, const MachineSpec& machine, const SearchOptions& options,
                          int axisSearchCount);

// The machine a project's plan is printed with: its machine, turned to the plan's rotation axis for 4-DOF.
MachineSpec printingMachineOf(const ProjectPlan& plan);

// Rebuilds the plan from its planes on `model` (planFromClippingPlanes with printingMachineOf(plan) and its
// options). The result's J_G are recomputed; compare them with plan.jgAfterMm2 to tell a changed model. The
// `cancelled` flag is carried over. Errors: those of planFromClippingPlanes (`where` = "plane K").
// Runs as long as the clipping does (seconds on large models); call it off the GUI thread.
Result<Decomposition> rebuildProjectPlan(const TriangleMesh& model, const ProjectPlan& plan);

// Writes the project to `path` atomically (beside it, then renamed into place). Everything is checked first,
// with loadProject's own checks, so a file that would not load back is never written.
// Errors: InvalidParameter (a field out of range or inconsistent: the message names it, e.g. "model.sample
// is not a sample MultiDir knows"), WriteFailed (the folder is missing or not writable: the message says why).
Status saveProject(const Project& project, const std::string& path);

// Reads and checks a project file: schema and version (a newer version is refused), every field's type and
// range, unit vectors, a known sample id, checksum form, plane count. The first violation is returned naming
// the file and the field: "kitten.multidir: plan.clippingPlanes[1].normal is not a unit vector". Unknown
// fields are ignored. The model file itself is not opened (a moved model is the caller's to report).
// Errors: FileNotFound, TooLarge, MalformedFile (invalid JSON, a missing field or a wrong type),
// InvalidParameter (a machine or search setting out of range).
Result<Project> loadProject(const std::string& path);

}  // namespace multidir::core
