#include "multidir/core/supports/support_options.h"

#include <cmath>
#include <string>

namespace multidir::core {
namespace {

Error outOfRange(const std::string& field, const std::string& range, double value) {
  return Error{ErrorCode::InvalidParameter,
               "the support option " + field + " must be " + range + " (got " + std::to_string(value) + ")", field};
}

}  // namespace

Status validate(const SupportOptions& o) {
  if (!(o.samplingSpacingMm > 0.1 && o.samplingSpacingMm <= 100.0))
    return outOfRange("samplingSpacingMm", "above 0.1 and at most 100 mm (2 suits a 0.4 mm nozzle, 3 a 0.8 mm one)",
                      o.samplingSpacingMm);
  if (!(o.strutAngleDegrees >= 0.0 && o.strutAngleDegrees <= 80.0))
    return outOfRange("strutAngleDegrees", "between 0 and 80 degrees", o.strutAngleDegrees);
  if (!(o.torqueLambda >= 0.0 && std::isfinite(o.torqueLambda)))
    return outOfRange("torqueLambda", "a finite number >= 0", o.torqueLambda);
  if (!(o.tipLengthMm > 0.0 && o.tipLengthMm <= 50.0))
    return outOfRange("tipLengthMm", "above 0 and at most 50 mm", o.tipLengthMm);
  if (!(o.contactRadiusMm > 0.0 && o.contactRadiusMm <= o.samplingSpacingMm / 4.0))
    return outOfRange("contactRadiusMm", "above 0 and at most a quarter of the sampling spacing", o.contactRadiusMm);
  if (o.strutSides < 3 || o.strutSides > 64)
    return outOfRange("strutSides", "between 3 and 64", o.strutSides);
  if (!(o.alphaMaxDegrees >= 0.0 && o.alphaMaxDegrees < 90.0))
    return outOfRange("alphaMaxDegrees", "at least 0 and below 90 degrees", o.alphaMaxDegrees);
  if (!(o.supportedBandMm >= 0.0 && o.supportedBandMm <= 100.0))
    return outOfRange("supportedBandMm", "between 0 and 100 mm", o.supportedBandMm);
  if (!(o.maxWallSlideDegrees >= 0.0 && o.maxWallSlideDegrees <= 89.0))
    return outOfRange("maxWallSlideDegrees", "between 0 and 89 degrees", o.maxWallSlideDegrees);
  return Done{};
}

}  // namespace multidir::core
