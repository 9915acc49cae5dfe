// The apart machine never leaves more support than the multi-directional plan (docs/apart.md, "Never more
// support than the multi-directional plan"): of its plans, the cheapest priced one whose J_G apart is at most
// the default 5-DOF plan's printed apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "multidir/core/apart/apart_plan.h"
#include "multidir/core/search/decompose.h"
#include "search/apart_choice.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::core::detail::ApartCandidate;
using multidir::core::detail::apartChoiceNote;
using multidir::core::detail::chooseApartCandidate;
using multidir::core::detail::PartPrice;

namespace {

MachineSpec machineOf(MachineKind kind) {
  MachineSpec machine;
  machine.kind = kind;
  machine.up = Vec3::UnitY();  // the shared models stand on +Y (their README)
  machine.rotationAxis = platformFrameX(machine.up);
  return machine;
}

Decomposition searched(const std::string& model, MachineKind kind) {
  JobContext job;
  auto result = decompose(multidir::test::loadSharedModel(model), machineOf(kind), SearchOptions{}, job);
  if (!result.ok()) throw std::runtime_error(result.error().describe());
  return std::move(result).value();
}

// The test: `multidir apart MODEL`'s plan, printed apart with the bed under every part, has no more
// J_G than the model's default 5-DOF plan, with the default part cost.
void expectApartNoMoreThanFiveDof(const std::string& model) {
  const Decomposition fiveDof = searched(model, MachineKind::TiltRotate);
  const Result<ApartPlan> apart = apartPlan(searched(model, MachineKind::Apart));
  ASSERT_TRUE(apart.ok()) << apart.error().describe();
  EXPECT_LE(apart->jgMm2, fiveDof.jgAfterMm2);
}

}  // namespace

// The three models where the apart search alone, paying 240 mm^2 a part, left more J_G than the 5-DOF plan.
TEST(ApartSearch, FertilityApartHasNoMoreJgThanItsFiveDofPlan) { expectApartNoMoreThanFiveDof("fertility.off"); }
TEST(ApartSearch, CheburashkaApartHasNoMoreJgThanItsFiveDofPlan) { expectApartNoMoreThanFiveDof("cheburashka.off"); }
TEST(ApartSearch, ScrewdriverApartHasNoMoreJgThanItsFiveDofPlan) { expectApartNoMoreThanFiveDof("screwdriver.off"); }

TEST(ApartSearch, TheKittensPlanComesFromItsOwnSearchWhereThatHasLessJgAndCostsLess) {
  // The kitten apart: J_G about 0 with 3 parts; its 5-DOF plan printed apart has J_G 11.76 mm^2 with as many
  // parts. Which of the apart search's plans is cheapest depends on their cut faces (docs/apart.md).
  const Decomposition plan = searched("kitten.off", MachineKind::Apart);
  std::string notes;
  for (const std::string& note : plan.statistics.notes) notes += note + "\n";
  EXPECT_TRUE(std::any_of(plan.statistics.notes.begin(), plan.statistics.notes.end(),
                          [](const std::string& note) { return note.rfind("the apart search's ", 0) == 0; }))
      << notes;
}

TEST(ApartChoice, TheCheapestPricedPlanAmongThoseThatKeepTheBoundIsChosen) {
  const std::vector<ApartCandidate> candidates{
      {"the apart search's best", 100.0, 5},              // priced at 240: 100 + 4 x 240 = 1,060
      {"the apart search's plan with 1 cuts", 300.0, 2},  // 540, but more J_G than the bound
      {"the 5-DOF plan printed apart", 200.0, 8},         // the bound; 1,880
  };
  EXPECT_EQ(chooseApartCandidate(candidates, PartPrice{240.0, 0.0}, candidates.back().jgApartMm2), 0);
  // Parts free: the least J_G under the bound.
  EXPECT_EQ(chooseApartCandidate(candidates, PartPrice{0.0, 0.0}, candidates.back().jgApartMm2), 0);
  // Without a bound the two-part plan would be the cheapest.
  EXPECT_EQ(chooseApartCandidate(candidates, PartPrice{240.0, 0.0}, 1e9), 1);
}

TEST(ApartChoice, ACutFaceCostsItsAreaSoTheSmallerCutFacesWinAtEqualSupportAndParts) {
  const std::vector<ApartCandidate> candidates{
      {"the apart search's best", 0.0, 3, 2000.0},                // 2 x 120 + 0.28 x 2,000 = 800
      {"the apart search's plan with 2 cuts", 0.0, 3, 500.0},     // 240 + 140 = 380
      {"the 5-DOF plan printed apart", 0.0, 3, 2000.0},
  };
  EXPECT_EQ(chooseApartCandidate(candidates, PartPrice{120.0, 0.28}, 0.0), 1);
  EXPECT_DOUBLE_EQ(multidir::core::detail::pricedMm2(candidates[1], PartPrice{120.0, 0.28}), 380.0);
  // At no price per cut face the first of equal prices is taken.
  EXPECT_EQ(chooseApartCandidate(candidates, PartPrice{120.0, 0.0}, 0.0), 0);
}

TEST(ApartChoice, TheFiveDofPlanIsChosenWhenEveryApartPlanHasMoreJg) {
  // Fertility's numbers before the bound (docs/apart.md): the apart search's best priced lower, with more J_G.
  const std::vector<ApartCandidate> candidates{{"the apart search's best", 870.93, 5},
                                               {"the 5-DOF plan printed apart", 555.44, 8}};
  const int chosen = chooseApartCandidate(candidates, PartPrice{240.0, 0.0}, candidates.back().jgApartMm2);
  ASSERT_EQ(chosen, 1);
  const std::string note = apartChoiceNote(candidates[1], candidates[0], candidates[1], PartPrice{240.0, 0.0});
  EXPECT_NE(note.find("the 5-DOF plan printed apart (J_G apart 555.44 mm^2, 8 parts"), std::string::npos) << note;
  EXPECT_NE(note.find("the apart search's best (J_G apart 870.93 mm^2, 5 parts) had more J_G apart than it"),
            std::string::npos)
      << note;
}
