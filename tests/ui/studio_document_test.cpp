// The studio document's invariants, without a window: what a new model, up, plan or sliced job clears, and
// the print run's pin on the device session's job.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QUndoCommand>
#include <QUndoStack>
#include <cmath>
#include <memory>

#include "multidir/core/search/pose_search.h"
#include "ui/document/studio_document.h"

namespace multidir::ui {
namespace {

LoadedModel modelNamed(const QString& name) {
  LoadedModel model;
  model.name = name;
  model.mesh = std::make_shared<const core::TriangleMesh>();
  return model;
}

SearchRun planWithRegions(int regions) {
  auto plan = std::make_shared<core::Decomposition>();
  for (int k = 0; k < regions; ++k) plan->regions.emplace_back();
  SearchRun run;
  run.plan = plan;
  return run;
}

PrintJob slicedJobFor(const SearchRun& run) {
  PrintJob job;
  job.plan = run.plan;
  for (std::size_t k = 0; k < run.plan->regions.size(); ++k) job.steps.push_back({"step.gcode", 60.0});
  return job;
}

// One edit on the history, as the plan editor pushes them.
void pushEdit(StudioDocument& document) {
  document.editHistory()->push(new QUndoCommand(QStringLiteral("Move plane 1")));
}

UpPose poseFrom(const core::Vec3& platformUp, const core::Vec3& up) {
  UpPose pose;
  pose.up = up.normalized();
  pose.pose.platformUp = platformUp;
  return pose;
}

TEST(StudioDocument, NewModelClearsThePlanItsEditHistoryAndTheSlicedJob) {
  StudioDocument document;
  document.setModel(modelNamed(QStringLiteral("kitten.off")));
  const SearchRun run = planWithRegions(3);
  document.setPlan(run);
  pushEdit(document);
  ASSERT_TRUE(document.setSlicedJob(slicedJobFor(run)).ok());

  document.setModel(modelNamed(QStringLiteral("bunny.off")));
  EXPECT_FALSE(document.plan().has_value());
  EXPECT_EQ(document.editHistory()->count(), 0);
  EXPECT_FALSE(document.slicedJob().has_value());
  EXPECT_EQ(document.sessionJob().plan, nullptr);
}

TEST(StudioDocument, NewModelDropsThePoseAndGoesBackToTheUpThePoseSearchStartedFrom) {
  StudioDocument document;
  document.setModel(modelNamed(QStringLiteral("bunny.off")));
  document.setUpPose(poseFrom(core::Vec3::UnitZ(), core::Vec3(0.3, -0.5, 0.8)));
  ASSERT_TRUE(document.upPose().has_value());
  QSignalSpy upChanged(&document, &StudioDocument::upChanged);

  document.setModel(modelNamed(QStringLiteral("fertility.off")));
  EXPECT_FALSE(document.upPose().has_value());
  EXPECT_EQ(document.up(), core::Vec3::UnitZ());
  EXPECT_EQ(document.machine().up, core::Vec3::UnitZ());
  EXPECT_EQ(upChanged.count(), 1);
}

TEST(StudioDocument, NewModelTurnsTheMachineTurnedWithThePoseBack) {
  StudioDocument document;
  core::MachineSpec rotary;
  rotary.kind = core::MachineKind::RotaryPlatform;
  rotary.rotationAxis = core::Vec3::UnitX();
  document.setMachine(rotary);
  document.setModel(modelNamed(QStringLiteral("bunny.off")));
  const UpPose pose = poseFrom(core::Vec3::UnitZ(), core::Vec3(0.6, 0.0, 0.8));
  document.setUpPose(pose);
  rotary.up = core::Vec3::UnitZ();
  document.setMachine(core::machineForPose(rotary, pose.up));  // as "Use this pose" turns it
  ASSERT_GT((document.machine().rotationAxis - core::Vec3::UnitX()).norm(), 0.1);

  document.setModel(modelNamed(QStringLiteral("fertility.off")));
  EXPECT_LT((document.machine().rotationAxis - core::Vec3::UnitX()).norm(), 1e-9);
  EXPECT_LT(std::abs(document.machine().rotationAxis.dot(document.up())), 1e-9);
}

TEST(StudioDocument, NewModelKeepsAnUpTheUserChoseUnlessTheModelBringsItsOwn) {
  StudioDocument document;
  document.setUp(core::Vec3::UnitY());
  document.setModel(modelNamed(QStringLiteral("kitten.off")));
  EXPECT_EQ(document.up(), core::Vec3::UnitY());
  LoadedModel sample = modelNamed(QStringLiteral("snowman"));
  sample.naturalUp = core::Vec3(0.0, 0.0, 2.0);
  document.setModel(sample);
  EXPECT_EQ(document.up(), core::Vec3::UnitZ());
}

TEST(StudioDocument, AnotherUpClearsThePlanAndTheSameUpKeepsIt) {
  StudioDocument document;
  document.setModel(modelNamed(QStringLiteral("kitten.off")));
  document.setPlan(planWithRegions(3));
  document.setUp(core::Vec3(0.0, 0.0, 5.0));  // the same direction
  EXPECT_TRUE(document.plan().has_value());
  document.setUp(core::Vec3::UnitX());
  EXPECT_FALSE(document.plan().has_value());
}

TEST(StudioDocument, NewPlanClearsTheSlicedJobAndStartsTheEditHistoryAgain) {
  StudioDocument document;
  const SearchRun first = planWithRegions(3);
  document.setPlan(first);
  pushEdit(document);
  ASSERT_TRUE(document.setSlicedJob(slicedJobFor(first)).ok());

  document.setPlan(planWithRegions(2));
  EXPECT_FALSE(document.slicedJob().has_value());
  EXPECT_EQ(document.editHistory()->count(), 0);
}

TEST(StudioDocument, EditedPlanKeepsItsEditHistoryButNotTheSlicedJob) {
  StudioDocument document;
  const SearchRun first = planWithRegions(3);
  document.setPlan(first);
  pushEdit(document);
  ASSERT_TRUE(document.setSlicedJob(slicedJobFor(first)).ok());

  document.setEditedPlan(planWithRegions(3));
  EXPECT_EQ(document.editHistory()->count(), 1);
  EXPECT_FALSE(document.slicedJob().has_value());
}

TEST(StudioDocument, SupportsAttachedLaterDropTheJobSlicedWithoutThem) {
  StudioDocument document;
  const SearchRun run = planWithRegions(2);
  document.setPlan(run);
  ASSERT_TRUE(document.setSlicedJob(slicedJobFor(run)).ok());
  EXPECT_FALSE(document.attachSupports(planWithRegions(2).plan, nullptr, QString()));  // another plan's
  EXPECT_TRUE(document.slicedJob().has_value());
  EXPECT_TRUE(document.attachSupports(run.plan, std::make_shared<const std::vector<core::SupportSet>>(2), QString()));
  EXPECT_FALSE(document.slicedJob().has_value());
  ASSERT_NE(document.plan()->supports, nullptr);
  EXPECT_EQ(document.plan()->supports->size(), 2u);
}

TEST(StudioDocument, JobSlicedFromAnotherPlanIsRefused) {
  StudioDocument document;
  const SearchRun old = planWithRegions(3);
  document.setPlan(old);
  document.setPlan(planWithRegions(3));
  const core::Status refused = document.setSlicedJob(slicedJobFor(old));
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("another plan"), std::string::npos) << refused.error().message;
  EXPECT_FALSE(document.slicedJob().has_value());
}

ApartPrint apartPrintOf(const SearchRun& run) {
  ApartPrint print;
  print.plan = run.plan;
  print.result = std::make_shared<const apart::ApartResult>();
  return print;
}

TEST(StudioDocument, PlanPrintedApartGoesWithAnyNewOrEditedPlanAndAnotherModel) {
  StudioDocument document;
  document.setModel(modelNamed(QStringLiteral("kitten.off")));
  SearchRun run = planWithRegions(3);
  document.setPlan(run);
  QSignalSpy changed(&document, &StudioDocument::apartPrintChanged);
  ASSERT_TRUE(document.setApartPrint(apartPrintOf(run)).ok());
  EXPECT_EQ(changed.size(), 1);

  run = planWithRegions(3);
  document.setEditedPlan(run);
  EXPECT_FALSE(document.apartPrint().has_value());
  ASSERT_TRUE(document.setApartPrint(apartPrintOf(run)).ok());
  run = planWithRegions(2);
  document.setPlan(run);
  EXPECT_FALSE(document.apartPrint().has_value());
  ASSERT_TRUE(document.setApartPrint(apartPrintOf(run)).ok());
  document.setModel(modelNamed(QStringLiteral("bunny.off")));
  EXPECT_FALSE(document.apartPrint().has_value());
  EXPECT_EQ(changed.size(), 6);  // three set, three dropped
}

TEST(StudioDocument, PlanPrintedApartFromAnotherPlanIsRefused) {
  StudioDocument document;
  const SearchRun old = planWithRegions(3);
  document.setPlan(old);
  document.setPlan(planWithRegions(3));
  const core::Status refused = document.setApartPrint(apartPrintOf(old));
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("another plan"), std::string::npos) << refused.error().message;
  EXPECT_FALSE(document.apartPrint().has_value());
}

TEST(StudioDocument, SessionJobIsThePlanShownWithItsSlicedGcode) {
  StudioDocument document;
  EXPECT_EQ(document.sessionJob().plan, nullptr);
  const SearchRun run = planWithRegions(3);
  document.setPlan(run);
  EXPECT_EQ(document.sessionJob().plan, run.plan);
  EXPECT_TRUE(document.sessionJob().steps.empty());
  ASSERT_TRUE(document.setSlicedJob(slicedJobFor(run)).ok());
  EXPECT_EQ(document.sessionJob().steps.size(), 3u);
  document.clearPlan();
  EXPECT_EQ(document.sessionJob().plan, nullptr);
}

TEST(StudioDocument, RunningPrintRunKeepsItsJobWhateverTheModelAndPlanBecome) {
  StudioDocument document;
  document.setModel(modelNamed(QStringLiteral("kitten.off")));
  const SearchRun run = planWithRegions(3);
  document.setPlan(run);
  ASSERT_TRUE(document.setSlicedJob(slicedJobFor(run)).ok());
  const core::Result<PrintJob> pinned = document.pinSessionJob();
  ASSERT_TRUE(pinned.ok());
  QSignalSpy sessionJobChanged(&document, &StudioDocument::sessionJobChanged);

  document.setModel(modelNamed(QStringLiteral("bunny.off")));
  document.setPlan(planWithRegions(5));
  EXPECT_EQ(document.sessionJob().plan, run.plan);
  EXPECT_EQ(document.sessionJob().steps.size(), 3u);
  EXPECT_EQ(sessionJobChanged.count(), 0);

  document.unpinSessionJob();
  EXPECT_EQ(document.sessionJob().plan, document.plan()->plan);
  EXPECT_EQ(document.sessionJob().plan->regions.size(), 5u);
}

TEST(StudioDocument, SecondPrintRunCannotTakeTheSessionJobFromTheFirst) {
  StudioDocument document;
  document.setPlan(planWithRegions(2));
  ASSERT_TRUE(document.pinSessionJob().ok());
  const core::Result<PrintJob> second = document.pinSessionJob();
  ASSERT_FALSE(second.ok());
  EXPECT_NE(second.error().message.find("already holds"), std::string::npos) << second.error().message;
}

TEST(StudioDocument, PrintRunWithoutAPlanIsRefused) {
  StudioDocument document;
  document.setModel(modelNamed(QStringLiteral("bunny.off")));
  const core::Result<PrintJob> refused = document.pinSessionJob();
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("no plan"), std::string::npos) << refused.error().message;
  EXPECT_FALSE(document.isSessionJobPinned());
}

}  // namespace
}  // namespace multidir::ui
