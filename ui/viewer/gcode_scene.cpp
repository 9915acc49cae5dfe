#include "ui/viewer/gcode_scene.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <vector>

#include "ui/common/region_palette.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// Extrusions drawn thicker than travels, so the part reads first; unsupported extrusions thicker still and in
// one warning colour; all unlit (their colours are exact).
constexpr float kExtrusionWidthPixels = 2.0f;
constexpr float kUnsupportedWidthPixels = 3.0f;
constexpr float kTravelWidthPixels = 1.0f;

// `segments` as lines: two points each, coloured by their step when `byStep`.
void fillLines(vtkPolyData* data, const std::vector<const ToolpathSegment*>& segments, bool byStep) {
  const std::size_t count = segments.size();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(2 * count));
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  lines->AllocateExact(static_cast<vtkIdType>(count), static_cast<vtkIdType>(2 * count));
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetName("step colours");
  colours->SetNumberOfComponents(3);
  if (byStep) colours->SetNumberOfTuples(static_cast<vtkIdType>(count));
  for (std::size_t i = 0; i < count; ++i) {
    const ToolpathSegment& s = *segments[i];
    const auto a = static_cast<vtkIdType>(2 * i);
    points->SetPoint(a, s.from.x(), s.from.y(), s.from.z());
    points->SetPoint(a + 1, s.to.x(), s.to.y(), s.to.z());
    const vtkIdType ends[2] = {a, a + 1};
    lines->InsertNextCell(2, ends);
    if (byStep) {
      const QColor c = regionColor(s.step - 1);
      const unsigned char rgb[3] = {static_cast<unsigned char>(c.red()), static_cast<unsigned char>(c.green()),
                                    static_cast<unsigned char>(c.blue())};
      colours->SetTypedTuple(static_cast<vtkIdType>(i), rgb);
    }
  }
  data->Initialize();
  data->SetPoints(points);
  data->SetLines(lines);
  if (byStep) data->GetCellData()->SetScalars(colours);
  data->Modified();
}

// The first `count` of `segments` whose mark is `unsupported`.
std::vector<const ToolpathSegment*> prefixOf(const std::vector<ToolpathSegment>& segments, std::size_t count,
                                             bool unsupported) {
  std::vector<const ToolpathSegment*> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    if (segments[i].unsupported == unsupported) out.push_back(&segments[i]);
  return out;
}

vtkSmartPointer<vtkActor> linesActor(vtkPolyData* data, float widthPixels) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  property->LightingOff();
  property->SetLineWidth(widthPixels);
  actor->PickableOff();
  actor->VisibilityOff();
  return actor;
}

}  // namespace

GcodeScene::GcodeScene(vtkRenderer* renderer)
    : m_renderer(renderer),
      m_extrusionData(vtkSmartPointer<vtkPolyData>::New()),
      m_travelData(vtkSmartPointer<vtkPolyData>::New()),
      m_unsupportedData(vtkSmartPointer<vtkPolyData>::New()) {
  m_extrusionActor = linesActor(m_extrusionData, kExtrusionWidthPixels);
  auto* extrusionMapper = static_cast<vtkPolyDataMapper*>(m_extrusionActor->GetMapper());
  extrusionMapper->SetScalarModeToUseCellData();
  extrusionMapper->SetColorModeToDirectScalars();
  extrusionMapper->ScalarVisibilityOn();
  m_travelActor = linesActor(m_travelData, kTravelWidthPixels);
  m_travelActor->GetMapper()->ScalarVisibilityOff();
  const QColor travel = MeshViewerWidget::gcodeTravelColor();
  m_travelActor->GetProperty()->SetColor(travel.redF(), travel.greenF(), travel.blueF());
  // Unsupported extrusions are left out of the step-coloured lines and drawn apart, so nothing covers them
  // at the same depth.
  m_unsupportedActor = linesActor(m_unsupportedData, kUnsupportedWidthPixels);
  m_unsupportedActor->GetMapper()->ScalarVisibilityOff();
  const QColor warning = unsupportedExtrusionColor();
  m_unsupportedActor->GetProperty()->SetColor(warning.redF(), warning.greenF(), warning.blueF());
  m_renderer->AddActor(m_extrusionActor);
  m_renderer->AddActor(m_travelActor);
  m_renderer->AddActor(m_unsupportedActor);
}

GcodeScene::~GcodeScene() {
  m_renderer->RemoveActor(m_extrusionActor);
  m_renderer->RemoveActor(m_travelActor);
  m_renderer->RemoveActor(m_unsupportedActor);
}

void GcodeScene::setPreview(std::shared_ptr<const GcodePreview> preview) {
  m_preview = std::move(preview);
  m_layerLimit = m_preview ? m_preview->layerCount() : 0;
  rebuild();
}

void GcodeScene::clear() { setPreview(nullptr); }

void GcodeScene::setLayerLimit(int layers) {
  const int limit = m_preview ? std::clamp(layers, 0, m_preview->layerCount()) : 0;
  if (limit == m_layerLimit) return;
  m_layerLimit = limit;
  rebuild();
}

void GcodeScene::setTravelVisible(bool visible) {
  if (visible == m_travelVisible) return;
  m_travelVisible = visible;
  rebuild();
}

int GcodeScene::extrusionLinesShown() const {
  return (m_extrusionActor->GetVisibility() ? static_cast<int>(m_extrusionData->GetNumberOfLines()) : 0) +
         unsupportedLinesShown();
}

int GcodeScene::unsupportedLinesShown() const {
  return m_unsupportedActor->GetVisibility() ? static_cast<int>(m_unsupportedData->GetNumberOfLines()) : 0;
}

int GcodeScene::travelLinesShown() const {
  return m_travelActor->GetVisibility() ? static_cast<int>(m_travelData->GetNumberOfLines()) : 0;
}

void GcodeScene::rebuild() {
  if (!m_preview) {
    m_extrusionData->Initialize();
    m_travelData->Initialize();
    m_unsupportedData->Initialize();
    m_extrusionActor->VisibilityOff();
    m_travelActor->VisibilityOff();
    m_unsupportedActor->VisibilityOff();
    return;
  }
  const std::size_t extrusions = m_preview->extrusionsUpTo(m_layerLimit);
  const std::vector<const ToolpathSegment*> supported = prefixOf(m_preview->extrusions, extrusions, false);
  fillLines(m_extrusionData, supported, true);
  m_extrusionActor->SetVisibility(!supported.empty());
  const std::vector<const ToolpathSegment*> unsupported = prefixOf(m_preview->extrusions, extrusions, true);
  fillLines(m_unsupportedData, unsupported, false);
  m_unsupportedActor->SetVisibility(!unsupported.empty());
  const std::size_t travels = m_travelVisible ? m_preview->travelsUpTo(m_layerLimit) : 0;
  fillLines(m_travelData, prefixOf(m_preview->travels, travels, false), false);
  m_travelActor->SetVisibility(travels > 0);
}

}  // namespace multidir::ui
