// The apart machine promises never more support than the multi-directional plan (docs/apart.md): its part
// cost makes its own search stop cutting where a cut saves less support than a part costs, so on its own it
// may end with more J_G than a 5-DOF arm's plan, which pays nothing per region. The choice below keeps the
// price per part and adds the bound: the cheapest plan, priced, among those with no more J_G apart than the
// 5-DOF plan printed apart (which is always one of them).
#include "search/apart_search.h"

#include <chrono>
#include <cmath>
#include <optional>

#include "common/fixed_text.h"
#include "multidir/core/apart/apart_plan.h"
#include "multidir/core/search/plan_from_planes.h"
#include "search/apart_choice.h"
#include "search/run_decomposition.h"

namespace multidir::core::detail {
namespace {

// Bounds are compared with this slack (mm^2): the same plan measured twice agrees to rounding.
constexpr double kBoundSlackMm2 = 1e-6;

std::string mm2(double value) { return detail::fixedText(value, 2); }

std::string partsText(int parts) { return std::to_string(parts) + (parts == 1 ? " part" : " parts"); }
std::string cutsText(std::size_t cuts) { return std::to_string(cuts) + (cuts == 1 ? " cut" : " cuts"); }

// The plan printed apart on a printer without a size limit: J_G apart and the parts.
Result<ApartCandidate> measuredApart(const Decomposition& plan, const SearchOptions& options, std::string name) {
  ApartOptions apart;
  apart.alphaMaxDegrees = options.alphaMaxDegrees;
  apart.supportedBandMm = options.supportedBandMm;
  const Result<ApartPlan> parts = apartPlan(plan, apart);
  // Without a size limit nothing is cut further, and a plan's closed regions always give parts.
  if (!parts.ok())
    return Error{ErrorCode::Internal, name + " cannot be printed apart: " + parts.error().describe(), "apart search"};
  double cutFaceMm2 = 0.0;
  for (const ApartJoint& joint : parts->joints) cutFaceMm2 += joint.areaMm2;
  return ApartCandidate{std::move(name), parts->jgMm2, static_cast<int>(parts->parts.size()), cutFaceMm2};
}

// The model's default multi-directional plan: the 5-DOF arm of MachineSpec's defaults, standing the model on
// the same up, searched with the same options (alpha, band, scheme; the part cost is the apart machine's).
MachineSpec defaultFiveDof(const MachineSpec& apart) {
  MachineSpec fiveDof;
  fiveDof.kind = MachineKind::TiltRotate;
  fiveDof.up = apart.up;
  fiveDof.rotationAxis = platformFrameX(apart.up);
  fiveDof.platformRadiusMm = apart.platformRadiusMm;
  fiveDof.platformMarginMm = apart.platformMarginMm;
  return fiveDof;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

double pricedMm2(const ApartCandidate& candidate, const PartPrice& price) {
  return candidate.jgApartMm2 + price.perPartMm2 * static_cast<double>(candidate.parts - 1) +
         price.perCutFaceMm2 * candidate.cutFaceMm2;
}

int chooseApartCandidate(const std::vector<ApartCandidate>& candidates, const PartPrice& price, double boundMm2) {
  int chosen = -1;
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    const ApartCandidate& c = candidates[static_cast<std::size_t>(i)];
    if (c.jgApartMm2 > boundMm2 + kBoundSlackMm2) continue;
    if (chosen < 0 || pricedMm2(c, price) < pricedMm2(candidates[static_cast<std::size_t>(chosen)], price))
      chosen = i;
  }
  return chosen;
}

std::string apartChoiceNote(const ApartCandidate& chosen, const ApartCandidate& searchBest, const ApartCandidate& bound,
                            const PartPrice& price) {
  std::string note = chosen.name + " (J_G apart " + mm2(chosen.jgApartMm2) + " mm^2, " + partsText(chosen.parts) +
                     ", cut faces " + mm2(chosen.cutFaceMm2) + " mm^2; priced " + mm2(pricedMm2(chosen, price)) +
                     " mm^2 at " + mm2(price.perPartMm2) + " mm^2 per part after the first and " +
                     mm2(price.perCutFaceMm2) + " per mm^2 of cut face) is the cheapest plan with no more J_G apart than ";
  note += chosen.name == bound.name
              ? "itself, the bound"
              : "the 5-DOF plan printed apart (" + mm2(bound.jgApartMm2) + " mm^2, " + partsText(bound.parts) + ")";
  if (chosen.name == searchBest.name) return note;
  note += ": the apart search's best (J_G apart " + mm2(searchBest.jgApartMm2) + " mm^2, " +
          partsText(searchBest.parts) + ") ";
  if (searchBest.jgApartMm2 > bound.jgApartMm2 + kBoundSlackMm2)
    note += "had more J_G apart than it";
  else
    note += "costs more priced (" + mm2(pricedMm2(searchBest, price)) + " mm^2)";
  return note;
}

Result<Decomposition> searchedAndPolished(const TriangleMesh& model, const MachineSpec& machine,
                                          const SearchOptions& options, JobContext& job,
                                          const SearchProgressSink& progress, const Result<SearchProxy>* proxy) {
  if (!needsProxy(model, options)) return searchedPolishedChoice(model, machine, options, job, progress);
  const ProxySearchRun search = [&](const TriangleMesh& mesh, const SearchOptions& o, const PlatformRegion& p) {
    return Result<Decomposition>(searchedPolishedChoice(mesh, machine, o, job, progress, p));
  };
  return proxy ? searchedOnProxy(model, machine, options, job, *proxy, search)
               : runProxyDecomposition(model, machine, options, job, search);
}

Result<Decomposition> decomposeApart(const TriangleMesh& model, const MachineSpec& machine,
                                     const SearchOptions& options, JobContext& job, const StagedProgress& progress,
                                     const Result<SearchProxy>* proxy) {
  const auto start = std::chrono::steady_clock::now();
  const SearchProgressSink apartStage = progress.stage(0), fiveDofStage = progress.stage(1);
  // The apart search's plans: its best (polished) and, on the full mesh, its best for every other number of cuts.
  std::vector<Decomposition> plans;
  std::vector<Decomposition> finalists;
  // A huge model: one proxy for both searches (the 5-DOF one stands on the same up), made once.
  std::optional<Result<SearchProxy>> ownProxy;
  if (needsProxy(model, options) && !proxy) proxy = &ownProxy.emplace(makeSearchProxy(model, machine.up, options));
  if (needsProxy(model, options)) {
    Result<Decomposition> searched = searchedAndPolished(model, machine, options, job, apartStage, proxy);
    if (!searched.ok()) return searched.error();
    plans.push_back(std::move(*searched));
  } else {
    plans.push_back(polishedIfAsked(
        model, machine, options, runDecomposition(model, machine, options, job, apartStage, std::nullopt, &finalists),
        job, apartStage));
  }
  if (plans.front().cancelled || job.isCancelled()) return std::move(plans.front());
  const double searchSeconds = secondsSince(start);

  // The bound: the default 5-DOF plan, its planes cut again on the apart machine (every region on the bed).
  const auto fiveDofStart = std::chrono::steady_clock::now();
  Result<Decomposition> fiveDof =
      searchedAndPolished(model, defaultFiveDof(machine), options, job, fiveDofStage, proxy);
  if (!fiveDof.ok()) return fiveDof.error();
  const bool fiveDofCancelled = fiveDof->cancelled;
  Result<Decomposition> fiveDofApart = planFromClippingPlanes(model, machine, options, fiveDof->clippingPlanes);
  // The apart machine drops criteria and keeps the rest, so it accepts every 5-DOF plan; else the plan as it
  // is, which apartPlan prints apart the same way.
  Decomposition boundPlan = fiveDofApart.ok() ? std::move(*fiveDofApart) : std::move(*fiveDof);
  const double fiveDofSeconds = secondsSince(fiveDofStart);

  for (Decomposition& finalist : finalists) plans.push_back(std::move(finalist));
  plans.push_back(std::move(boundPlan));
  std::vector<ApartCandidate> candidates;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    const std::string name = i == 0 ? "the apart search's best"
                             : i + 1 == plans.size()
                                 ? "the 5-DOF plan printed apart"
                                 : "the apart search's plan with " + cutsText(plans[i].clippingPlanes.size());
    Result<ApartCandidate> measured = measuredApart(plans[i], options, name);
    if (!measured.ok()) return measured.error();
    candidates.push_back(std::move(*measured));
  }
  const ApartCandidate bound = candidates.back();
  const PartPrice price{options.partCostMm2, options.cutFaceCost};
  // Never -1: the 5-DOF plan printed apart keeps its own bound.
  const auto chosenPlan =
      static_cast<std::size_t>(chooseApartCandidate(candidates, price, bound.jgApartMm2));
  ApartCandidate chosenCandidate = candidates[chosenPlan];

  Decomposition plan = std::move(plans[chosenPlan]);
  const bool isFinalist = chosenPlan != 0 && chosenPlan + 1 != plans.size();
  if (isFinalist && options.polish) {
    // A finalist comes from the search unpolished: polished, it is kept when it still keeps the bound and
    // costs no more.
    Decomposition polished = polishedIfAsked(model, machine, options, plan, job, fiveDofStage);
    const Result<ApartCandidate> measured = measuredApart(polished, options, chosenCandidate.name);
    if (measured.ok() && measured->jgApartMm2 <= bound.jgApartMm2 + kBoundSlackMm2 &&
        pricedMm2(*measured, price) <= pricedMm2(chosenCandidate, price)) {
      plan = std::move(polished);
      chosenCandidate = *measured;
    }
  }
  plan.cancelled = job.isCancelled() || fiveDofCancelled;
  plan.statistics.notes.push_back(apartChoiceNote(chosenCandidate, candidates.front(), bound, price));
  plan.statistics.notes.push_back("the apart search took " + mm2(searchSeconds) +
                                  " s, the 5-DOF search for the bound " + mm2(fiveDofSeconds) + " s");
  plan.statistics.seconds = secondsSince(start);
  return plan;
}

}  // namespace multidir::core::detail
