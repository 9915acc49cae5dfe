#include "ui/viewer/cell_scene.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>

#include <algorithm>
#include <cmath>

#include "multidir/robot/arm_frames.h"
#include "ui/viewer/cell_colors.h"
#include "ui/viewer/mesh_to_polydata.h"

namespace multidir::ui {
namespace {

vtkSmartPointer<vtkTransform> transformOf(const Eigen::Isometry3d& pose) {
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix->SetElement(r, c, pose.matrix()(r, c));
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->SetMatrix(matrix);
  return transform;
}

vtkSmartPointer<vtkActor> actorOf(vtkAlgorithm* source, const double rgb[3]) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->PickableOff();
  return actor;
}

vtkSmartPointer<vtkActor> actorOf(vtkPolyData* data, const double rgb[3]) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->PickableOff();
  return actor;
}

// Unlit: drawn in exactly its colour (the tests find it by it).
void unlit(vtkActor* actor) {
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
}

// A unit cylinder (vtkCylinderSource: radius 1, height 1, along y, centred) placed from `a` to `b`.
Eigen::Isometry3d cylinderPose(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = 0.5 * (a + b);
  const Eigen::Vector3d d = b - a;
  if (d.norm() > 1e-9) pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), d.normalized()).toRotationMatrix();
  return pose;
}

void placeCylinder(vtkActor* actor, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius) {
  vtkSmartPointer<vtkTransform> t = transformOf(cylinderPose(a, b));
  t->Scale(radius, std::max((b - a).norm(), 1e-3), radius);
  actor->SetUserTransform(t);
}

vtkSmartPointer<vtkActor> unitCylinderActor(const double rgb[3]) {
  vtkNew<vtkCylinderSource> source;
  source->SetRadius(1.0);
  source->SetHeight(1.0);
  source->SetResolution(32);
  source->CappingOn();
  return actorOf(source.Get(), rgb);
}

vtkSmartPointer<vtkPolyData> partData(const std::vector<const core::TriangleMesh*>& meshes) {
  core::TriangleMesh all;
  for (const core::TriangleMesh* mesh : meshes) {
    const auto base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), mesh->vertices.begin(), mesh->vertices.end());
    for (const auto& t : mesh->triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    all.origins.insert(all.origins.end(), mesh->origins.begin(), mesh->origins.end());
  }
  return toPolyData(all);
}

// How thick the arm is drawn: a drawing choice, not a dimension the checks use (the table check has its own
// housing estimate in robot/): about UR's look, 45 mm on the UR5.
double housingRadiusMm(const robot::ArmModel& arm) { return 0.055 * (std::abs(arm.a[1]) + std::abs(arm.a[2])); }

}  // namespace

CellScene::CellScene(vtkRenderer* renderer, vtkRenderer* overlay) : m_renderer(renderer), m_overlay(overlay) {}

CellScene::~CellScene() { setMotion(nullptr); }

void CellScene::setMotion(std::shared_ptr<const CellMotion> motion) {
  auto removeAll = [this] {
    for (auto& a : m_links) m_renderer->RemoveActor(a);
    for (auto& a : m_fixed) m_renderer->RemoveActor(a);
    for (vtkActor* a : {m_platform.Get(), m_earlierPart.Get(), m_stepPart.Get(), m_toolpath.Get()})
      if (a) m_renderer->RemoveActor(a);
    for (vtkActor* a : {m_point.Get(), m_nozzle.Get(), m_warningMarker.Get()})
      if (a) m_overlay->RemoveActor(a);
    if (m_warningText) m_overlay->RemoveActor2D(m_warningText);
    m_links.clear();
    m_fixed.clear();
    m_earlierPart = nullptr;
    m_stepPart = nullptr;
    m_toolpath = nullptr;
  };
  removeAll();
  m_motion = std::move(motion);
  m_builtStep = -1;
  m_position = {};
  if (!m_motion) return;
  build();
  pose();
}

void CellScene::build() {
  const robot::Cell& cell = m_motion->cell;
  // Joint housings (one per joint, along its axis) then the links between consecutive DH origins.
  for (int i = 0; i < 6; ++i) m_links.push_back(unitCylinderActor(kCellArmRgb));
  for (int i = 0; i < 6; ++i) m_links.push_back(unitCylinderActor(kCellArmRgb));
  for (auto& a : m_links) m_renderer->AddActor(a);

  m_platform = unitCylinderActor(kCellPlatformRgb);
  m_renderer->AddActor(m_platform);

  // The fixed extruder: its bodies, translucent so the nozzle and the part show through.
  for (const robot::CollisionBox& b : cell.boxes) {
    vtkNew<vtkCubeSource> cube;
    cube->SetXLength(b.sizeMm.x());
    cube->SetYLength(b.sizeMm.y());
    cube->SetZLength(b.sizeMm.z());
    auto actor = actorOf(cube.Get(), kCellBodyRgb);
    actor->SetUserTransform(transformOf(b.pose));
    actor->GetProperty()->SetOpacity(0.35);
    m_fixed.push_back(actor);
  }
  for (const robot::CollisionCylinder& c : cell.cylinders) {
    auto actor = unitCylinderActor(kCellBodyRgb);
    placeCylinder(actor, c.baseMm, c.baseMm + c.lengthMm * c.axis, c.radiusMm);
    actor->GetProperty()->SetOpacity(0.35);
    m_fixed.push_back(actor);
  }
  // The table: a square slab under the arm's reach, its top at tableZMm.
  {
    const double reach = std::abs(cell.arm.a[1]) + std::abs(cell.arm.a[2]) + cell.arm.d[3] + cell.arm.d[5];
    vtkNew<vtkCubeSource> slab;
    slab->SetXLength(1.5 * reach);
    slab->SetYLength(1.5 * reach);
    slab->SetZLength(10.0);
    slab->SetCenter(0.0, 0.0, cell.tableZMm - 5.0);
    auto actor = actorOf(slab.Get(), kCellTableRgb);
    m_fixed.push_back(actor);
  }
  for (auto& a : m_fixed) m_renderer->AddActor(a);

  // The markers are sized to the arm (the view frames the whole arm): a few pixels across at any model.
  const double armSize = std::abs(cell.arm.a[1]) + std::abs(cell.arm.a[2]);
  // The nozzle: a cone whose point is the tip, opening up the axis into the extruder.
  {
    vtkNew<vtkConeSource> cone;
    const double height = 0.03 * armSize;
    cone->SetHeight(height);
    cone->SetRadius(0.01 * armSize);
    cone->SetResolution(32);
    // vtkConeSource points along +x from its centre; the tip at +height/2.
    const Eigen::Vector3d down = -cell.nozzleAxis.normalized();
    cone->SetDirection(down.x(), down.y(), down.z());
    const Eigen::Vector3d centre = cell.nozzleTipMm - 0.5 * height * down;
    cone->SetCenter(centre.x(), centre.y(), centre.z());
    m_nozzle = actorOf(cone.Get(), kCellNozzleRgb);
    unlit(m_nozzle);
    m_overlay->AddActor(m_nozzle);
  }
  // The toolpath point and the warning marker: unlit spheres on the overlay, sized by the arm.
  const auto overlaySphere = [&](double radius, const double* rgb) {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(16);
    vtkSmartPointer<vtkActor> actor = actorOf(sphere.Get(), rgb);
    unlit(actor);
    m_overlay->AddActor(actor);
    return actor;
  };
  m_point = overlaySphere(0.006 * armSize, kCellToolpathPointRgb);
  m_warningMarker = overlaySphere(0.014 * armSize, kCellWarningRgb);
  m_warningText = vtkSmartPointer<vtkTextActor>::New();
  m_warningText->GetTextProperty()->SetColor(kCellWarningRgb[0], kCellWarningRgb[1], kCellWarningRgb[2]);
  m_warningText->GetTextProperty()->SetFontSize(15);
  m_warningText->GetTextProperty()->SetBackgroundColor(1.0, 1.0, 1.0);
  m_warningText->GetTextProperty()->SetBackgroundOpacity(0.85);
  m_warningText->SetDisplayPosition(10, 10);
  m_overlay->AddActor2D(m_warningText);
}

void CellScene::setPosition(CellPosition position) {
  if (!m_motion || m_motion->steps.empty()) return;  // the cell alone: the arm stays at home
  position.step = std::clamp(position.step, 0, static_cast<int>(m_motion->steps.size()) - 1);
  const auto& samples = m_motion->steps[static_cast<std::size_t>(position.step)].samples;
  position.sample = std::clamp(position.sample, 0, std::max(0, static_cast<int>(samples.size()) - 1));
  m_position = position;
  pose();
}

void CellScene::pose() {
  if (!m_motion) return;
  const robot::Cell& cell = m_motion->cell;
  if (m_motion->steps.empty()) {  // the cell alone (the reach map shown before a job is): the arm at home
    poseArm(robot::platformPose(cell, cell.home), cell.home);
    m_point->VisibilityOff();
    m_warningMarker->VisibilityOff();
    m_warningText->VisibilityOff();
    return;
  }
  const robot::StepMotion& step = m_motion->steps[static_cast<std::size_t>(m_position.step)];
  const Eigen::Isometry3d fileToPlatform = step.platformToFile.inverse();

  // The part and the toolpath of the step, in the platform frame: rebuilt when the step changes.
  if (m_builtStep != m_position.step) {
    if (m_earlierPart) m_renderer->RemoveActor(m_earlierPart);
    if (m_stepPart) m_renderer->RemoveActor(m_stepPart);
    if (m_toolpath) m_renderer->RemoveActor(m_toolpath);
    std::vector<const core::TriangleMesh*> earlier;
    for (int s = 0; s < m_position.step; ++s) {
      earlier.push_back(&m_motion->steps[static_cast<std::size_t>(s)].region);
      earlier.push_back(&m_motion->steps[static_cast<std::size_t>(s)].supports);
    }
    m_earlierPart = actorOf(partData(earlier), kCellPartRgb);
    m_stepPart = actorOf(partData({&step.region, &step.supports}), kCellPartRgb);
    m_stepPart->GetProperty()->SetOpacity(0.6);
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t i = 1; i < step.samples.size(); ++i) {
      if (!step.samples[i].extrudes) continue;
      const Eigen::Vector3d a = fileToPlatform * step.samples[i - 1].nozzleFileMm;
      const Eigen::Vector3d b = fileToPlatform * step.samples[i].nozzleFileMm;
      const vtkIdType ids[2] = {points->InsertNextPoint(a.data()), points->InsertNextPoint(b.data())};
      lines->InsertNextCell(2, ids);
    }
    auto toolpath = vtkSmartPointer<vtkPolyData>::New();
    toolpath->SetPoints(points);
    toolpath->SetLines(lines);
    m_toolpath = actorOf(toolpath, kCellToolpathRgb);
    unlit(m_toolpath);
    m_renderer->AddActor(m_earlierPart);
    m_renderer->AddActor(m_stepPart);
    m_renderer->AddActor(m_toolpath);
    m_builtStep = m_position.step;
  }

  // The pose: the sample's, or home when the step was refused before its first move.
  Eigen::Isometry3d platform = robot::platformPose(cell, cell.home);
  robot::Joints joints = cell.home;
  const robot::MotionSample* sample = nullptr;
  if (!step.samples.empty()) {
    sample = &step.samples[static_cast<std::size_t>(m_position.sample)];
    platform = robot::platformPoseAt(step, *sample);
    joints = sample->joints;
  }
  for (vtkActor* a : {m_earlierPart.Get(), m_stepPart.Get(), m_toolpath.Get()}) a->SetUserTransform(transformOf(platform));
  poseArm(platform, joints);

  const Eigen::Vector3d point = sample ? Eigen::Vector3d(platform * (fileToPlatform * sample->nozzleFileMm)) : cell.nozzleTipMm;
  m_point->SetPosition(point.x(), point.y(), point.z());
  m_point->SetVisibility(sample != nullptr);

  // The warning: the red marker where the step's path stops (its last converted point, carried with the part),
  // or at the nozzle when it stopped before its first move.
  if (step.warning) {
    const Eigen::Vector3d where =
        step.samples.empty() ? cell.nozzleTipMm : Eigen::Vector3d(platform * (fileToPlatform * step.samples.back().nozzleFileMm));
    m_warningMarker->SetPosition(where.x(), where.y(), where.z());
    m_warningMarker->VisibilityOn();
    std::string text = step.warning->text;
    // Wrapped for the view: at most about 110 characters a line.
    std::size_t column = 0;
    for (std::size_t i = 0; i < text.size(); ++i, ++column) {
      if (column > 100 && text[i] == ' ') {
        text[i] = '\n';
        column = 0;
      }
    }
    m_warningText->SetInput(text.c_str());
    m_warningText->VisibilityOn();
  } else {
    m_warningMarker->VisibilityOff();
    m_warningText->SetInput("");
    m_warningText->VisibilityOff();
  }
}

// The platform disc at `platform` and the arm at `joints`.
void CellScene::poseArm(const Eigen::Isometry3d& platform, const robot::Joints& joints) {
  const robot::Cell& cell = m_motion->cell;
  // The platform disc: its top in the TCP's xy plane, its thickness below.
  placeCylinder(m_platform, platform * Eigen::Vector3d(0, 0, -cell.platformThicknessMm), platform * Eigen::Vector3d(0, 0, -0.2),
                cell.platformRadiusMm);

  // The arm: each joint's housing along its axis (z of the frame before it), the links between the origins.
  const auto frames = robot::armFrames(cell.arm, joints);
  const double housing = housingRadiusMm(cell.arm);
  for (std::size_t j = 0; j < 6; ++j) {
    const Eigen::Vector3d origin = frames[j].translation();
    const Eigen::Vector3d axis = frames[j].linear().col(2);
    placeCylinder(m_links[j], origin - 0.6 * housing * axis, origin + 0.6 * housing * axis, 0.8 * housing);
  }
  for (std::size_t j = 0; j < 6; ++j) {
    placeCylinder(m_links[6 + j], frames[j].translation(), frames[j + 1].translation(), 0.6 * housing);
  }
}

core::Vec3 CellScene::toolpathPointDrawn() const {
  if (!m_point) return core::Vec3::Zero();
  double p[3];
  m_point->GetPosition(p);
  return {p[0], p[1], p[2]};
}

core::Vec3 CellScene::partCentreDrawn() const {
  if (!m_stepPart) return core::Vec3::Zero();
  const double* c = m_stepPart->GetCenter();
  return {c[0], c[1], c[2]};
}

std::string CellScene::warningShown() const {
  if (!m_warningText || !m_warningText->GetVisibility() || !m_warningText->GetInput()) return {};
  return m_warningText->GetInput();
}

bool CellScene::warningMarkerShown() const { return m_warningMarker && m_warningMarker->GetVisibility() != 0; }


}  // namespace multidir::ui
