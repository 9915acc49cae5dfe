#pragma once
// Parameters of the decomposition search (the paper's Section IV), with their defaults.
#include <functional>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"
#include "multidir/core/search/candidate_planes.h"

namespace multidir::core {

enum class SearchScheme {
  Greedy,             // paper Eq. 7: the plane with the largest J_L, again and again
  ConstrainedGreedy,  // paper Eq. 8: largest J_L among planes leaving the part above risk-free, else Eq. 7
  Beam,               // paper Algorithm 1: beam-guided search with progressive relaxation
};

const char* schemeName(SearchScheme scheme);  // "greedy", "cgreedy", "beam"
Result<SearchScheme> parseScheme(const std::string& text);

// The apart machine's price of one more part, as the risky area whose supports cost as much print time,
// measured with PrusaSlicer (docs/apart.md, "The price of a part"): a fixed price per part (mm^2: its dowels'
// print time) and a price per mm^2 of its cut face (mm^2 of J_G per mm^2: the solid layers on both sides).
inline constexpr double kDefaultPartCostMm2 = 120.0;
inline constexpr double kDefaultCutFaceCost = 0.28;

struct SearchOptions {
  SearchScheme scheme = SearchScheme::Beam;
  int beamWidth = 10;                       // b, >= 1
  double alphaMaxDegrees = kDefaultAlphaMaxDegrees;
  CandidateOptions candidates;
  // w: every region above a plane keeps at least V(M)/w. The paper used 10; with J_G counted honestly
  // (docs/jg-definition.md) a belly or an underside is only printed risk-free from a smaller region of its
  // own, and 40 took the median of the nine shared models from 4.4 % to 1.8 % of J_G before (bench/). Regions
  // that do not pay for themselves are removed after the search (minPlaneGain*).
  double minVolumeDivisor = 40.0;
  // The beam search runs at this many region scales, w, 2w, 4w, ..., side by side, each with
  // beamWidth / volumeScales beams (rounded up), and keeps the best plan of all. No single w suits every
  // model: a knight's mane and ears are printed risk-free only from regions near V/80, while at V/80 a
  // bunny's beam spends its levels on small cuts and ends worse than at V/40 (bench/, docs/search.md).
  // 1: the paper's single beam at w. 1 to 4.
  int volumeScales = 2;
  double initialDeltaMm2 = 0.1;             // progressive relaxation starts at R < delta ...
  double deltaGrowth = 5.0;                 // ... and multiplies delta by this until the beams are full
  double diversityCosine = 0.95;            // two children of one parent are too close when |n.n'| > this
  double diversityOffsetMm = 2.0;           // ... and their offsets differ by less than this
  // Beam search: the best `beamWidth` candidates of a level are refined between the lattice normals, in this
  // many rounds of a pattern search (half the lattice spacing, then halved each round); 0: off. The paper's
  // closing remark: sampled planes miss the real optimum; refining them locally is how to get closer.
  int refinementRounds = 3;
  double supportedBandMm = kDefaultSupportedBandMm;  // height above the platform (only) that the bed supports
  // Printable regions: no region, the one on the platform included, is thinner than this along its printing
  // direction (its height from its base plane, or from the bed, to its top). A sliver a few layers thick can
  // neither be printed reliably nor hold the region above it. >= 0.
  double minRegionHeightMm = 2.0;
  // A plane is kept only if it pays for itself: each region costs a platform move and a seam, so a plane
  // whose removal would raise J_G by less than max(minPlaneGainMm2, minPlaneGainPercent % of J_G before) is
  // removed from the plan after the search.
  double minPlaneGainPercent = 1.0;
  double minPlaneGainMm2 = 1.0;
  // The apart machine (docs/apart.md): each plane makes one more part, to print, fit with dowels and glue, and
  // a cut face whose two sides are printed solid, so a plane is kept only if its removal would raise J_G by at
  // least partCostMm2 + cutFaceCost x its cut face's area (mm^2, one side of the joint) as well. Ignored by
  // other machines. partCostMm2 in [0, 1e9] mm^2; cutFaceCost in [0, 1000] mm^2 per mm^2.
  double partCostMm2 = kDefaultPartCostMm2;
  double cutFaceCost = kDefaultCutFaceCost;
  double platformToleranceMm = kDefaultPlatformToleranceMm;  // how close a solid must reach to touch the platform
  int threads = 0;                          // 0: all hardware threads
  // Models with more faces than this are searched on a decimated proxy of about this many faces; the planes
  // found are then applied to the full mesh, each offset polished there, and every number is measured on the
  // full mesh (docs/search.md). 0: always search the full mesh. 0 or in [1000, 10^7].
  int proxyFaces = 50000;
  // Polishing (docs/search.md, "Polishing"): after the search, every plane's normal and offset are moved
  // continuously, one plane at a time in printing order, to lower J_G as the final plan measures it, with every
  // constraint the search keeps. The search only sees sampled planes; the paper's Discussion names this as the
  // way to the optimum between them.
  bool polish = true;
  // How finely polishing goes: its steps (2 degrees and half the offset step at first) halve this many times
  // less one; each level costs about as much as the one before. 1 to 6. At 1, search and polishing together
  // took 1.0 to 2.0 times the CPU time of the search alone on the shared models (docs/search.md, "Polishing").
  int polishEffort = 1;
  // Also polish the search's best plan for every other number of cuts (each without its unpaid planes) that
  // may beat the search's own plan polished, and deliver the least J_G after polishing (docs/search.md,
  // "Polishing the finalists"): which plan polishes best is not the one that was best before polishing (the
  // bunny's 254-normal lattice: 2.08 % delivered, 1.08 % from a finalist). A finalist's polish is given up
  // part-way once its J_G falls too slowly to win, so on by default: it costs the shared models a few plans.
  bool polishFinalists = true;
  // After polishing, search the plan's later planes again from the state after each of its first k planes
  // (both greedy chains and a beam of two) and deliver a lower plan found there, polished (docs/search.md,
  // "Searching the tails again"). It changes which regions the plan chooses, which polishing cannot: the
  // fertility statue 4.55 -> 2.19 %, the bunny 1.24 -> 0.95 %, the knight 7.19 -> 6.18 % of J_G before. Off by
  // default: it took about twice the default search's CPU on the shared models (the knight three times).
  bool searchTails = false;
};

Status validate(const SearchOptions& options);

// The volume divisor of the beam search's region scale s (0 = w, the coarsest): w * 2^s. Every region the
// search at that scale cuts off keeps at least V / this. s is clamped to the valid scales [0, 3].
[[nodiscard]] double volumeDivisorOfScale(const SearchOptions& options, int scale);

// The volume divisor of the beam search's finest scale: w * 2^(volumeScales - 1) (w for the greedy schemes).
[[nodiscard]] double finestVolumeDivisor(const SearchOptions& options);

// The deepest level the search may reach (progress says "level k of this", k the deepest level a beam reached):
// every region cut off at scale w keeps at least V/w, so no plan has more than ceil(w) + 1 cuts, and the scales
// run side by side, so the finest scale's bound is the search's.
[[nodiscard]] int maxSearchLevels(const SearchOptions& options);

// What the search reports while it runs (on the thread that runs it).
struct SearchProgress {
  int level = 0;                 // clipping planes in the plans being extended (the deepest of the searches)
  int beamsAlive = 0;
  // The J_G of the best complete plan so far, the one Cancel delivers: it never rises during the search
  // (polishing then starts from the plan without its unpaid planes, docs/search.md "Progress and Cancel").
  double bestJgMm2 = 0.0;
  long long candidatesScored = 0;
  int axisIndex = -1;            // 4-DOF axis search: which axis (else -1)
  int axisCount = 0;
  // Polishing the found plan (after the search): true while it runs, with its share done in [0, 1].
  bool polishing = false;
  double polishFraction = 0.0;
  // decompose() runs one search, or, for the apart machine, two one after the other (its own, then the
  // default 5-DOF search for its bound, docs/apart.md): `stage` of `stageCount` (1-based) is the one
  // reporting; its level and best J_G restart with it. `fraction` is the share of all of them done, in
  // [0, 1], never decreasing over one decompose() (docs/search.md, "Progress and Cancel").
  int stage = 1;
  int stageCount = 1;
  double fraction = 0.0;
};
using SearchProgressSink = std::function<void(const SearchProgress&)>;

}  // namespace multidir::core
