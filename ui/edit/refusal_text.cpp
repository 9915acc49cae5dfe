#include "ui/edit/refusal_text.h"

#include <QCoreApplication>
#include <algorithm>
#include <string>

#include "ui/edit/plane_numbering.h"
#include "ui/common/error_text.h"

namespace multidir::ui {
namespace {

// The translation context of these sentences (lupdate reads Q_DECLARE_TR_FUNCTIONS).
class PlanEditRefusal {
  Q_DECLARE_TR_FUNCTIONS(PlanEditRefusal)
};

bool mentions(const core::Error& error, const char* words) { return error.message.find(words) != std::string::npos; }

}  // namespace

int refusedPlaneNumber(const core::Error& error) {
  const std::string prefix = "plane ";
  if (error.where.rfind(prefix, 0) != 0) return 0;
  try {
    return std::max(0, std::stoi(error.where.substr(prefix.size())));
  } catch (...) {
    return 0;
  }
}

QString refusalText(const core::Error& error, int planeCount) {
  const int clippingNumber = refusedPlaneNumber(error);
  const int plane = clippingNumber > 0 && clippingNumber <= planeCount
                        ? planeNumber(clippingNumber - 1, planeCount)
                        : clippingNumber;
  if (plane == 0 || error.code != core::ErrorCode::InvalidParameter) {
    return PlanEditRefusal::tr("The edit was not applied: %1 (%2)")
        .arg(errorHeadline(error.code), QString::fromStdString(error.describe()));
  }
  // Criterion III is tested before Criterion II: "Criterion II" is also a prefix of "Criterion III".
  if (mentions(error, "Criterion III"))
    return PlanEditRefusal::tr("Plane %1 would cut the platform region: move it up or tilt it less.").arg(plane);
  if (mentions(error, "Criterion II"))
    return PlanEditRefusal::tr(
               "Plane %1 would leave a piece below it that no longer stands on the platform: move or tilt it so "
               "that the part below stays in one piece on the platform.")
        .arg(plane);
  if (mentions(error, "cannot print along"))
    return PlanEditRefusal::tr(
               "The machine cannot print along the normal of plane %1: tilt it back within the machine's limits.")
        .arg(plane);
  if (mentions(error, "cuts nothing"))
    return PlanEditRefusal::tr("Plane %1 would cut nothing off: move it into the part it cuts.").arg(plane);
  if (mentions(error, "nothing below"))
    return PlanEditRefusal::tr("Plane %1 would leave nothing below it on the platform: move it up.").arg(plane);
  return PlanEditRefusal::tr("Plane %1 was refused: %2").arg(plane).arg(QString::fromStdString(error.message));
}

QString refusalText(const core::Error& error, int planeCount, int editedPlane) {
  const QString text = refusalText(error, planeCount);
  const int clippingNumber = refusedPlaneNumber(error);
  if (editedPlane < 0 || editedPlane >= planeCount || clippingNumber <= 0 || clippingNumber > planeCount ||
      clippingNumber - 1 == editedPlane || error.code != core::ErrorCode::InvalidParameter)
    return text;
  return PlanEditRefusal::tr("Plane %1 was not changed: with it there, plane %2 is refused. %3")
      .arg(planeNumber(editedPlane, planeCount))
      .arg(planeNumber(clippingNumber - 1, planeCount))
      .arg(text);
}

}  // namespace multidir::ui
