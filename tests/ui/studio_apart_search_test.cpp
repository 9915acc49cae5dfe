// The studio's Search dock offers the apart machine (docs/apart.md, "The studio"): the Machine panel lists it,
// the Search panel its prices of a part, the search runs it as the command line does (decompose() with
// MachineKind::Apart, the 5-DOF bound included), and Print apart then prints that plan.
#include <gtest/gtest.h>

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <algorithm>

#include "ui/document/studio_document.h"
#include "ui/document/search_run.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

constexpr int kSearchTimeoutMs = 300000;  // a guard against a hang: two searches on busy cores

TEST(StudioApartSearch, TheApartMachineIsOfferedWithItsPricesAndSearchedWithItsBound) {
  MainWindow window;
  test::showDefaultSample(window);
  auto* kinds = window.machinePanel()->findChild<QComboBox*>(QStringLiteral("machineKind"));
  ASSERT_NE(kinds, nullptr);
  const int apart = kinds->findData(static_cast<int>(core::MachineKind::Apart));
  ASSERT_GE(apart, 0) << "the Machine panel does not offer the apart machine";
  EXPECT_EQ(kinds->itemText(apart), QStringLiteral("Apart (plain printer, parts joined by dowels)"));

  auto* partCost = window.searchPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("partCost"));
  auto* cutFaceCost = window.searchPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("cutFaceCost"));
  ASSERT_NE(partCost, nullptr);
  ASSERT_NE(cutFaceCost, nullptr);
  EXPECT_FALSE(partCost->isEnabled()) << "a 5-DOF machine pays nothing per part";
  kinds->setCurrentIndex(apart);
  EXPECT_EQ(window.document()->machine().kind, core::MachineKind::Apart);
  EXPECT_TRUE(partCost->isEnabled());
  EXPECT_TRUE(cutFaceCost->isEnabled());
  EXPECT_EQ(partCost->value(), core::SearchOptions{}.partCostMm2);
  EXPECT_EQ(cutFaceCost->value(), core::SearchOptions{}.cutFaceCost);

  window.searchPanel()->setSearchOptions(test::quickSearchOptions());
  partCost->setValue(60.0);
  cutFaceCost->setValue(0.5);
  const core::SearchOptions options = window.searchPanel()->searchOptions();
  EXPECT_EQ(options.partCostMm2, 60.0);
  EXPECT_EQ(options.cutFaceCost, 0.5);

  QSignalSpy finished(&window, &MainWindow::searchFinished);
  ASSERT_TRUE(window.runSearch());
  ASSERT_TRUE(finished.wait(kSearchTimeoutMs)) << "the search did not finish";
  const SearchRun run = finished.front().front().value<SearchRun>();
  ASSERT_TRUE(run.plan);
  EXPECT_FALSE(run.plan->cancelled);
  // The apart machine's choice, as `multidir decompose --machine apart` makes it, at the panel's prices.
  const auto& notes = run.plan->statistics.notes;
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& note) {
    return note.find("mm^2 at 60.00 mm^2 per part after the first and 0.50 per mm^2 of cut face") != std::string::npos;
  })) << "no apart choice among the plan's notes";
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& note) {
    return note.find("the 5-DOF search for the bound") != std::string::npos;
  }));

  // Print apart prints that plan.
  auto* printApart = window.findChild<QAction*>(QStringLiteral("printApart"));
  ASSERT_NE(printApart, nullptr);
  EXPECT_TRUE(printApart->isEnabled());
}

}  // namespace
}  // namespace multidir::ui
