#include "multidir/core/search/search_options.h"

#include <algorithm>
#include <cmath>

namespace multidir::core {

const char* schemeName(SearchScheme scheme) {
  switch (scheme) {
    case SearchScheme::Greedy: return "greedy";
    case SearchScheme::ConstrainedGreedy: return "cgreedy";
    case SearchScheme::Beam: return "beam";
  }
  return "?";
}

Result<SearchScheme> parseScheme(const std::string& text) {
  if (text == "greedy") return SearchScheme::Greedy;
  if (text == "cgreedy") return SearchScheme::ConstrainedGreedy;
  if (text == "beam") return SearchScheme::Beam;
  return Error{ErrorCode::InvalidParameter, "'" + text + "' is not a scheme: use beam, greedy or cgreedy", "scheme"};
}

Status validate(const SearchOptions& o) {
  auto bad = [](const std::string& where, const std::string& rule) {
    return Status(Error{ErrorCode::InvalidParameter, where + " " + rule, where});
  };
  if (o.beamWidth < 1 || o.beamWidth > 1000) return bad("beam width", "must be between 1 and 1000");
  if (!(o.alphaMaxDegrees >= 0 && o.alphaMaxDegrees < 90)) return bad("alpha", "must be at least 0 and below 90 degrees");
  if (!(o.minVolumeDivisor >= 1 && o.minVolumeDivisor <= 1000))
    return bad("w", "(the minimal region volume is V/w) must be between 1 and 1000");
  if (o.volumeScales < 1 || o.volumeScales > 4) return bad("volume scales", "must be between 1 and 4");
  if (!(o.initialDeltaMm2 > 0 && std::isfinite(o.initialDeltaMm2))) return bad("delta", "must be a positive area in mm^2");
  if (!(o.deltaGrowth > 1 && o.deltaGrowth < 1000)) return bad("delta growth", "must be above 1 and below 1000");
  if (!(o.diversityCosine >= 0 && o.diversityCosine <= 1)) return bad("diversity cosine", "must be between 0 and 1");
  if (!(o.diversityOffsetMm >= 0 && o.diversityOffsetMm < 1e4)) return bad("diversity offset", "must be between 0 and 10000 mm");
  if (!(o.supportedBandMm >= 0 && o.supportedBandMm <= 100)) return bad("supported band", "must be between 0 and 100 mm");
  if (!(o.platformToleranceMm >= 0 && o.platformToleranceMm < 10)) return bad("platform tolerance", "must be between 0 and 10 mm");
  if (!(o.minRegionHeightMm >= 0 && o.minRegionHeightMm <= 1000))
    return bad("minimum region height", "must be between 0 and 1000 mm");
  if (!(o.minPlaneGainPercent >= 0 && o.minPlaneGainPercent <= 100))
    return bad("minimum plane gain", "must be between 0 and 100 % of J_G before");
  if (!(o.minPlaneGainMm2 >= 0 && o.minPlaneGainMm2 <= 1e9))
    return bad("minimum plane gain area", "must be between 0 and 1e9 mm^2");
  if (!(o.partCostMm2 >= 0 && o.partCostMm2 <= 1e9)) return bad("part cost", "must be between 0 and 1e9 mm^2");
  if (!(o.cutFaceCost >= 0 && o.cutFaceCost <= 1000))
    return bad("cut face cost", "must be between 0 and 1000 mm^2 of risky area per mm^2 of cut face");
  if (o.refinementRounds < 0 || o.refinementRounds > 10) return bad("refinement rounds", "must be between 0 (off) and 10");
  if (o.threads < 0 || o.threads > 256) return bad("threads", "must be between 0 (all) and 256");
  if (o.polishEffort < 1 || o.polishEffort > 6) return bad("polish effort", "must be between 1 and 6");
  if (o.proxyFaces != 0 && (o.proxyFaces < 1000 || o.proxyFaces > 10000000))
    return bad("proxy faces", "must be 0 (search the full mesh) or between 1000 and 10000000");
  return validate(o.candidates);
}

double volumeDivisorOfScale(const SearchOptions& options, int scale) {
  return std::ldexp(options.minVolumeDivisor, std::clamp(scale, 0, 3));
}

double finestVolumeDivisor(const SearchOptions& options) {
  if (options.scheme != SearchScheme::Beam) return options.minVolumeDivisor;
  return volumeDivisorOfScale(options, std::clamp(options.volumeScales, 1, 4) - 1);
}

int maxSearchLevels(const SearchOptions& options) {
  const int scales = options.scheme == SearchScheme::Beam ? std::clamp(options.volumeScales, 1, 4) : 1;
  // The finest scale's beam may go deepest: its regions are the smallest.
  return static_cast<int>(std::ceil(volumeDivisorOfScale(options, scales - 1))) + 1;
}

}  // namespace multidir::core
