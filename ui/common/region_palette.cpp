#include "ui/common/region_palette.h"

namespace multidir::ui {
namespace {

// Saturated, mid-bright colours (after Kelly's and Tableau's lists); ordered so that consecutive regions,
// which usually touch, differ most.
constexpr unsigned kRegionRgb[kRegionColorCount] = {
    0xe6194b, 0x3cb44b, 0xffe119, 0x4363d8, 0xf58231, 0x911eb4, 0x46f0f0, 0xf032e6,
    0xbcf60c, 0x008080, 0x9a6324, 0xfabebe, 0x800000, 0xaaffc3, 0x808000, 0xb39ddb,
};

constexpr QRgb kSupportRgb = 0x4010f0;
constexpr QRgb kUnsupportedRgb = 0xff00a0;

}  // namespace

QColor supportColor() { return QColor(kSupportRgb); }

QColor unsupportedExtrusionColor() { return QColor(kUnsupportedRgb); }

QColor regionColor(int index) {
  const int slot = (index < 0 ? 0 : index) % kRegionColorCount;
  return QColor(QRgb(kRegionRgb[slot]));
}

}  // namespace multidir::ui
