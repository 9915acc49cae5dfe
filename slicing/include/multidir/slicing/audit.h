#pragma once
// An independent check of a sliced job's machine code (`multidir audit JOB`, docs/slicing.md "Audit"): the
// G-code is replayed through the machine's kinematics, implemented here from the documented convention and not
// taken from core::machinePose, into the model's frame, and checked per step and in total:
//   (a) every extrusion lies inside its region or its supports, within half a line width;
//   (b) every extrusion rests on something printed before it, on the platform, or within the printable angle
//       of something printed before it (reported: it is what J_G predicts);
//   (c) the first layer of each step lies one layer height above its base plane;
//   (d) nothing is extruded while the filament is retracted;
//   (e) during every turn of the platform the nozzle clears everything printed so far.
#include <Eigen/Geometry>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/machine.h"

namespace multidir::slicing {

// The machine as the audit replays it (model frame, mm).
struct AuditMachine {
  core::MachineKind kind = core::MachineKind::TiltRotate;
  core::Vec3 up = core::Vec3::UnitZ();            // unit: the plan machine's up
  core::Vec3 rotationAxis = core::Vec3::UnitX();  // unit, 4-DOF: the platform's axis r
  core::Vec3 pivot = core::Vec3::Zero();          // the platform centre: every pose turns about it
};

// The audit's kinematics (docs/slicing.md "Audit"): model coordinates to the machine files' frame (up = +Z,
// the pivot at the origin). Platform frame: z = up, x = platformFrameX(up), y = up x x.
//  - 3-DOF: the platform frame.
//  - 4-DOF at `rotaryDegrees` θ: the part turned by -θ about r through the pivot (the platform's top tilts
//    towards up x r for positive θ).
//  - 5-DOF at tilt t, azimuth a: the part turned by t about the platform-frame axis (sin a, -cos a, 0) through
//    the pivot, so that the platform-frame direction (sin t cos a, sin t sin a, cos t) becomes vertical.
Eigen::Isometry3d auditModelToFile(const AuditMachine& machine, const core::MachineAngles& angles);

// A firmware axis at A degrees: the rest pose (3-DOF above) turned by -A about the files' +X through the
// origin (positive A tilts the platform's top towards +Y).
Eigen::Isometry3d firmwareAxisModelToFile(const AuditMachine& machine, double aDegrees);

// One rotary axis of a firmware-2axis printer as print-job.json records it (slicing.printer.axes.tilt /
// .rotation): the firmware's coordinate is zero + direction x the convention's angle.
struct AuditRotaryAxis {
  std::string letter;   // the G-code letter (U, V, B, C...)
  std::string stepper;  // Klipper's [manual_stepper] name
  double zeroDegrees = 0.0;
  double direction = 1.0;  // +1 or -1
  double minDegrees = -360.0;
  double maxDegrees = 360.0;
  // The convention's angle (radians) at the firmware coordinate `degrees`.
  double conventionRadians(double degrees) const;
};

// The two axes of a firmware-2axis printer (docs/slicing.md "Two firmware axes"), in printer coordinates.
struct AuditTwoAxes {
  AuditRotaryAxis tilt{"U", "tilt", 0.0, 1.0, -90.0, 90.0};
  AuditRotaryAxis rotation{"V", "rotation", 0.0, 1.0, -360.0, 360.0};
  bool tiltAlongX = true;                                      // else along the printer's Y
  double tiltHeightMm = 0.0;                                   // printer Z of the tilt axis
  Eigen::Vector2d rotationCenterMm = Eigen::Vector2d::Zero();  // printer XY of the rotation axis at tilt zero
  Eigen::Vector2d platformCenterMm = Eigen::Vector2d::Zero();  // printer XY of the files' frame's origin
  double platformZMm = 0.0;                                    // printer Z of the files' frame's origin
};

// Firmware coordinates of the two axes, degrees.
struct AuditAxisCoordinates {
  double tiltDegrees = 0.0;
  double rotationDegrees = 0.0;
};

// The two axes' lines in the files' frame: the tilt axis through `tiltPoint` along `tiltDirection` (fixed),
// the rotation axis through `rotationPoint` along +Z with the tilt at zero (it rides on the tilt cradle).
struct AuditAxisLines {
  core::Vec3 tiltPoint = core::Vec3::Zero();
  core::Vec3 tiltDirection = core::Vec3::UnitX();
  core::Vec3 rotationPoint = core::Vec3::Zero();
};
AuditAxisLines auditAxisLines(const AuditTwoAxes& axes);

// Two firmware axes at `at`: the rest pose `rest` (model to files' frame, the first step's pose from its plan
// angles), then the platform turned by +r about its normal through the rotation centre, then by -t about the
// tilt axis' line (r, t the convention's angles of the coordinates).
Eigen::Isometry3d twoAxisModelToFile(const AuditTwoAxes& axes, const Eigen::Isometry3d& rest,
                                     const AuditAxisCoordinates& at);

// The bead a step lays down (mm): from the printer profile, overridden by the slicer's own settings that
// close its G-code ("; layer_height = 0.2").
struct BeadGeometry {
  double widthMm = 0.45;            // extrusion_width, else nozzle_diameter x 1.125
  double layerHeightMm = 0.2;       // layer_height
  double firstLayerHeightMm = 0.2;  // first_layer_height
};

// One step of the job.
struct AuditStep {
  int index = 1;
  core::MachineAngles angles;
  core::Vec3 printingDirection = core::Vec3::UnitZ();                     // model frame, as print-job.json says
  Eigen::Isometry3d recordedModelToFile = Eigen::Isometry3d::Identity();  // print-job.json's modelToFile
  core::TriangleMesh region;    // model frame (the step file moved back by recordedModelToFile); a soup
  core::TriangleMesh supports;  // model frame; empty without supports
  // firmware-2axis: the axes' coordinates while the step prints (print-job.json slicing.steps[i].axisDegrees)
  std::optional<AuditAxisCoordinates> axisDegrees;
  std::string gcodeFile;        // "step-01.gcode"
  std::string gcode;            // its text
  BeadGeometry bead;
};

enum class AuditPlatform { None, FirmwareAxis, FirmwareTwoAxis, Modbus };

struct AuditJob {
  std::string directory;
  AuditMachine machine;
  AuditPlatform platform = AuditPlatform::Modbus;
  // Printer coordinates = files' frame + this: (platform_center.x, platform_center.y, platform_z).
  core::Vec3 printerOffset = core::Vec3::Zero();
  std::string rotaryAxis = "A";   // the platform's G-code axis letter (firmware axis)
  AuditTwoAxes twoAxes;           // FirmwareTwoAxis: the axes (print-job.json slicing.printer.axes)
  double alphaMaxDegrees = 45.0;  // the printable angle: the plan's search.alphaMaxDegrees when it is found
  std::vector<AuditStep> steps;
  std::string stitchedFile;  // "job.gcode", empty when there is none
  std::string stitchedGcode;
};

// Reads a job folder written by `multidir slice`: print-job.json (machine, pivot, steps, slicing), the step
// meshes (binary or ASCII STL), the G-code files, the printer profile named in slicing.printer.profile (its
// multidir.platform_center, platform_z, rotary_axis and bead settings) and, when the plan folder is still
// where print-job.json says, plan.json's search.alphaMaxDegrees (else 45 degrees). A firmware-2axis job: the
// axes from slicing.printer.axes (else the profile's), each step's slicing.steps[i].axisDegrees required.
// Errors: FileNotFound (the folder, print-job.json, a step file or G-code), MalformedFile (a field missing
// or of the wrong type, named with the file and its path in the JSON; a mesh that cannot be read), UnsupportedFormat (step meshes that
// are not STL), InvalidParameter (no "slicing": the job was not sliced).
core::Result<AuditJob> readAuditJob(const std::string& directory);

struct AuditOptions {
  std::optional<double> alphaMaxDegrees;  // overrides the job's printable angle
  double firstLayerToleranceMm = 0.05;    // (c): |gap - layer height| above this is a violation
  double retractToleranceMm = 1e-3;       // (d): retracted by more than this counts
  int worstClusters = 5;                  // (a), (b): places reported per program
};

// Where extrusion went wrong: one cluster of samples (a 5 mm cube of the model frame) in one step.
struct AuditPlace {
  int step = 1;
  std::string file;
  int line = 0;                                // the first G-code line of the cluster
  core::Vec3 modelPoint = core::Vec3::Zero();  // the samples' centroid, model frame
  double lengthMm = 0.0;                       // extrusion length in the cluster
  double worstMm = 0.0;                        // (a): the farthest sample's distance outside the solid
};

struct StepAudit {
  int step = 1;
  std::string file;             // the G-code file the step's extrusions are in
  double extrusionMm = 0.0;     // path length of the step's extrusions (after its marker)
  double skirtMm = 0.0;         // of which skirt and brim (;TYPE:Skirt/Brim): not held to (a)
  double outsideMm = 0.0;       // (a)
  double worstOutsideMm = 0.0;  // (a): farthest distance outside region and supports, beyond w/2
  double unsupportedMm = 0.0;   // (b)
  // (b) by the slicer's feature (";TYPE:" comment): "Overhang perimeter", "Bridge infill", "Internal infill"...
  std::map<std::string, double> unsupportedByFeatureMm;
  // (b): the lines of `file` whose extrusion is unsupported anywhere along it, ascending, each once (the
  // studio's preview marks them). Empty in a program's total: its lines are of several files.
  std::vector<int> unsupportedLines;
  double firstLayerGapMm = std::numeric_limits<double>::quiet_NaN();  // (c): lowest extrusion z - base z
  double expectedGapMm = 0.0;     // (c): first_layer_height (step 1) or layer_height
  double baseZMm = 0.0;           // (c): printer z of the step's base plane under the replayed pose
  int retractViolations = 0;      // (d): in the step's section (and the start sequence, for step 1)
  std::vector<int> retractLines;  // (d): the first few lines
  // (e) the turn after this step: nozzle z minus the highest point of the printed part over the turn; NaN
  // when no turn follows.
  double turnClearanceMm = std::numeric_limits<double>::quiet_NaN();
  double turnNozzleZMm = std::numeric_limits<double>::quiet_NaN();
  double turnSweptTopZMm = std::numeric_limits<double>::quiet_NaN();
  int turnLine = 0;  // the line that turns (stitched), or the program's last line (Modbus)
  bool firstLayerViolation = false;
  bool turnViolation = false;
  double unsupportedPercent() const { return extrusionMm > 0.0 ? 100.0 * unsupportedMm / extrusionMm : 0.0; }
};

// One replayed program: the step programs one after another, or the stitched job.gcode.
struct ProgramAudit {
  std::string name;  // "step programs", "step programs (each on its own)" (firmware axis) or "job.gcode"
  bool stitched = false;
  std::string followedAxes;  // stitched: the rotary axes the pose follows as replayed ("A", "U and V")
  std::vector<StepAudit> steps;
  StepAudit total;                        // sums; firstLayerGapMm: the largest deviation; turnClearanceMm: the least
  std::vector<AuditPlace> outsidePlaces;  // (a): the worst clusters, longest first
  std::vector<AuditPlace> unsupportedPlaces;  // (b): the worst clusters, longest first
};

struct AuditReport {
  std::vector<ProgramAudit> programs;
  // Findings that are not a per-step number, each naming the file (and line): a pose in print-job.json that
  // the kinematics disagree with, a platform angle in job.gcode other than the step's, an extrusion inside a
  // transition, a turn outside one or one that also moves the nozzle.
  std::vector<std::string> findings;
  int poseMismatches = 0;      // print-job.json poses and job.gcode angles that disagree with the kinematics
  int sequenceViolations = 0;  // extrusion in a transition, a turn outside one or with the nozzle moving
  double alphaMaxDegrees = 45.0;
  // Violations of (a) beyond tolerance, (c), (d), (e), pose mismatches and sequence violations: the job
  // fails the audit.
  bool failed() const;
  // (b) too, for --strict.
  bool hasUnsupported() const;
};

// Replays and checks every program of the job: for a Modbus platform the step programs one after another
// (the machine's state, the nozzle and the filament carried from one to the next); for a firmware axis (one or
// two) the stitched job.gcode and, each on its own, the step programs it was made of (two axes: each at the
// pose of its recorded axis coordinates). Progress: one share per
// program; cancellation is checked every few thousand moves. Errors: MalformedFile (a G-code line that is
// not G-code, or an arc move G2/G3, named with file and line), Cancelled.
core::Result<AuditReport> auditJob(const AuditJob& job, const AuditOptions& options, core::JobContext& context);

}  // namespace multidir::slicing
