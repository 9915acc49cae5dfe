#pragma once
// Units and default tolerances of MultiDir's core, in one place.
// Lengths are millimetres everywhere. Angles are radians inside core; a parameter or field that holds
// degrees says so in its name (alphaMaxDegrees) and is converted at the API edge with degToRad().

namespace multidir::core {

constexpr double kPi = 3.14159265358979323846;

constexpr double degToRad(double degrees) { return degrees * kPi / 180.0; }
constexpr double radToDeg(double radians) { return radians * 180.0 / kPi; }

// Two points closer than this (mm) are the same point when an STL's duplicate vertices are merged.
constexpr double kDefaultWeldToleranceMm = 1e-6;
// A face whose area is below this (mm^2) is degenerate.
constexpr double kDefaultDegenerateAreaMm2 = 1e-12;
// A point within this distance (mm) of a clipping plane is treated as lying on it.
constexpr double kDefaultPlaneToleranceMm = 1e-9;
// A face within this distance (mm) of the platform plane, and facing it, lies on the platform.
constexpr double kDefaultPlatformToleranceMm = 1e-3;
// The first layers of a print lie on the bed (or on the region below): a face's part within this height (mm)
// above the platform or a region's base plane is supported there. With 1 mm, J_G of the paper's kitten before
// decomposition comes out as the paper's (1481 mm^2 against 1481.36); with 0, its flat but faceted bottom
// would count 1263 mm^2 of risky faces that no printer supports.
constexpr double kDefaultSupportedBandMm = 1.0;
// The maximal self-supporting angle most FDM printers manage (the paper's alpha_max).
constexpr double kDefaultAlphaMaxDegrees = 45.0;

}  // namespace multidir::core
