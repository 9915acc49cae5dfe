#pragma once
// The apart machine's promise (docs/apart.md, "Never more support than the multi-directional plan"): of the
// plans it could return, the one with the least J_G apart plus the price of every part after the first, among
// those whose J_G apart is at most the model's default 5-DOF plan printed apart. Internal to core.
#include <string>
#include <vector>

namespace multidir::core::detail {

// One plan the apart machine may return, as printed apart (core::apartPlan, no build volume).
struct ApartCandidate {
  std::string name;  // for the plan's notes: "the apart search's best", "the 5-DOF plan printed apart"
  double jgApartMm2 = 0.0;
  int parts = 1;
  double cutFaceMm2 = 0.0;  // the joints' areas summed (one side of each)
};

// The price of the parts after the first, in risky area (SearchOptions::partCostMm2 and cutFaceCost).
struct PartPrice {
  double perPartMm2 = 0.0;
  double perCutFaceMm2 = 0.0;  // mm^2 of J_G per mm^2 of cut face
};

// J_G apart plus the price of every part after the first and of every cut face: what the apart machine
// minimises.
double pricedMm2(const ApartCandidate& candidate, const PartPrice& price);

// The index of the candidate with the least priced cost among those whose J_G apart is at most
// `boundMm2` (ties: the first). -1 when none keeps the bound.
int chooseApartCandidate(const std::vector<ApartCandidate>& candidates, const PartPrice& price, double boundMm2);

// The sentence the plan's notes carry: which candidate was chosen, and why, against the apart search's best
// (`searchBest`) and the bound's plan (`bound`).
std::string apartChoiceNote(const ApartCandidate& chosen, const ApartCandidate& searchBest, const ApartCandidate& bound,
                            const PartPrice& price);

}  // namespace multidir::core::detail
