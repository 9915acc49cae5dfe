// The undoable plan edits on a QUndoStack: exact states back and forth, and drags merged into one step.
#include "ui/edit/plan_edit_commands.h"

#include <gtest/gtest.h>

#include <QUndoStack>

namespace multidir::ui {
namespace {

// Records the states the commands apply.
class RecordingTarget : public PlanEditTarget {
 public:
  void applyEditState(const PlanEditState& state) override { applied.push_back(state); }
  std::vector<PlanEditState> applied;
};

PlanEditState withOffsets(std::initializer_list<double> offsets, int selected) {
  PlanEditState state;
  for (double offset : offsets) state.planes.push_back({core::Vec3::UnitZ(), offset});
  state.selectedPlane = selected;
  return state;
}

TEST(PlanEditCommands, UndoAndRedoApplyTheExactStatesBeforeAndAfter) {
  RecordingTarget target;
  QUndoStack stack;
  const PlanEditState before = withOffsets({10.0, 5.0}, -1);
  const PlanEditState after = withOffsets({10.0, 5.5}, 1);
  stack.push(new MovePlaneCommand(target, before, after, 1));
  ASSERT_EQ(target.applied.size(), 1u);  // pushing applies it
  stack.undo();
  stack.redo();
  ASSERT_EQ(target.applied.size(), 3u);
  EXPECT_TRUE(samePlanes(target.applied[1].planes, before.planes));
  EXPECT_EQ(target.applied[1].selectedPlane, -1);
  EXPECT_TRUE(samePlanes(target.applied[2].planes, after.planes));
  EXPECT_EQ(target.applied[2].selectedPlane, 1);
  // Plane 1 (0-based) of two is the lower one, the first the machine prints on: plane 1 in printing order.
  EXPECT_EQ(stack.undoText(), QStringLiteral("Move plane 1"));
}

TEST(PlanEditCommands, MovesOfOnePlaneInOneDragMergeIntoOneStep) {
  RecordingTarget target;
  QUndoStack stack;
  stack.push(new MovePlaneCommand(target, withOffsets({10.0}, 0), withOffsets({11.0}, 0), 0, 7));
  stack.push(new MovePlaneCommand(target, withOffsets({11.0}, 0), withOffsets({12.0}, 0), 0, 7));
  stack.push(new MovePlaneCommand(target, withOffsets({12.0}, 0), withOffsets({13.0}, 0), 0, 7));
  EXPECT_EQ(stack.count(), 1);
  stack.undo();
  EXPECT_TRUE(samePlanes(target.applied.back().planes, withOffsets({10.0}, 0).planes));
  stack.redo();
  EXPECT_TRUE(samePlanes(target.applied.back().planes, withOffsets({13.0}, 0).planes));
}

TEST(PlanEditCommands, TwoDragsTwoPlanesOrAMoveAndATiltStaySeparateSteps) {
  RecordingTarget target;
  QUndoStack stack;
  stack.push(new MovePlaneCommand(target, withOffsets({10.0, 5.0}, 0), withOffsets({11.0, 5.0}, 0), 0, 1));
  stack.push(new MovePlaneCommand(target, withOffsets({11.0, 5.0}, 0), withOffsets({12.0, 5.0}, 0), 0, 2));
  stack.push(new MovePlaneCommand(target, withOffsets({12.0, 5.0}, 1), withOffsets({12.0, 6.0}, 1), 1, 2));
  stack.push(new TiltPlaneCommand(target, withOffsets({12.0, 6.0}, 1), withOffsets({12.0, 7.0}, 1), 1, 2));
  // Edits typed in (no drag) never merge.
  stack.push(new MovePlaneCommand(target, withOffsets({12.0, 7.0}, 1), withOffsets({12.0, 8.0}, 1), 1));
  stack.push(new MovePlaneCommand(target, withOffsets({12.0, 8.0}, 1), withOffsets({12.0, 9.0}, 1), 1));
  EXPECT_EQ(stack.count(), 6);
}

TEST(PlanEditCommands, ADragBackToWhereItStartedLeavesNoStep) {
  RecordingTarget target;
  QUndoStack stack;
  stack.push(new AddPlaneCommand(target, withOffsets({}, -1), withOffsets({10.0}, 0), 0));
  stack.push(new MovePlaneCommand(target, withOffsets({10.0}, 0), withOffsets({12.0}, 0), 0, 3));
  stack.push(new MovePlaneCommand(target, withOffsets({12.0}, 0), withOffsets({10.0}, 0), 0, 3));
  EXPECT_EQ(stack.count(), 1);
  EXPECT_EQ(stack.undoText(), QStringLiteral("Add plane 1"));
}

TEST(PlanEditCommands, DeleteNamesThePlaneByItsNumberInPrintingOrder) {
  RecordingTarget target;
  QUndoStack stack;
  // The last plane cut (z = 2) is the lowest: the first one printed on.
  stack.push(new DeletePlaneCommand(target, withOffsets({10.0, 5.0, 2.0}, 2), withOffsets({10.0, 5.0}, 1), 2));
  EXPECT_EQ(stack.undoText(), QStringLiteral("Delete plane 1"));
  stack.undo();
  EXPECT_EQ(target.applied.back().planes.size(), 3u);
  EXPECT_EQ(target.applied.back().selectedPlane, 2);
}

}  // namespace
}  // namespace multidir::ui
