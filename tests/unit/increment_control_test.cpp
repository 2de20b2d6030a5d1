// Requirements: the increment controller's sizes, cut-backs, regrowth and recovery sequence; an increment cut below
// the nominal size measures its corrections against a nominal increment's motion.
#include <gtest/gtest.h>

#include "strandfem/solver/increment_controller.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {
namespace {

TEST(IncrementControl, CutIncrementIsMeasuredAgainstANominalIncrementsMotion) {
  // Last increment: 1/8 of the nominal 0.05 moved the strand by 0.02 (squared 4e-4); a nominal one would move 0.16.
  const double floor2 = cut_increment_motion_floor2(4e-4, 0.05 / 8, 0.05 / 16, 0.05);
  EXPECT_NEAR(std::sqrt(floor2), 0.16, 1e-12);
}

TEST(IncrementControl, NominalIncrementsAndTurnsOfTheLoadingKeepTheirOwnMotion) {
  EXPECT_EQ(cut_increment_motion_floor2(4e-4, 0.05, 0.05, 0.05), 0.0);       // nominal size: its own motion
  EXPECT_EQ(cut_increment_motion_floor2(4e-4, 0.0, 0.05 / 4, 0.05), 0.0);    // no last increment (a reversal)
  EXPECT_GT(cut_increment_motion_floor2(4e-4, 0.05, 0.05 / 4, 0.05), 0.0);   // cut after a nominal increment
  EXPECT_NEAR(cut_increment_motion_floor2(4e-4, 0.05, 0.05 / 4, 0.05), 4e-4, 1e-15);
}

constexpr int kEasy = 2;    // corrections of an easy increment (at most a quarter of the 25 allowed)
constexpr int kHard = 10;

TEST(IncrementController, NominalIncrementsLandOnTheGrid) {
  IncrementController control;
  control.begin_step(4, 0.0);
  std::vector<double> targets;
  while (!control.step_done()) {
    targets.push_back(control.target());
    control.converged(kEasy);
  }
  ASSERT_EQ(targets.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(targets[k], 0.25 * (k + 1), 1e-15);
  EXPECT_EQ(control.sizes().converged_increments, 4);
}

TEST(IncrementController, CutBackHalvesAndRegrowsAfterThreeEasyIncrementsAtTheCap) {
  IncrementController control;
  control.begin_step(4, 0.0);
  EXPECT_FALSE(control.recovering());
  EXPECT_EQ(control.failed(false), Recovery::kHalve);
  EXPECT_EQ(control.cutbacks(), 1);
  EXPECT_TRUE(control.recovering());
  EXPECT_NEAR(control.target(), 0.125, 1e-15);
  control.converged(kEasy);
  EXPECT_EQ(control.cutbacks(), 0);
  EXPECT_TRUE(control.recovering());  // converged, but still below the nominal size
  // Back on the grid point 0.25 first; the cap (1/8) holds until three easy increments at it.
  EXPECT_NEAR(control.target(), 0.25, 1e-15);
  control.converged(kEasy);
  EXPECT_NEAR(control.target(), 0.375, 1e-15);
  control.converged(kEasy);  // the third easy increment at the cap: it doubles to the nominal size
  EXPECT_NEAR(control.sizes().largest_size, 0.25, 1e-15);
  EXPECT_FALSE(control.recovering());
  EXPECT_NEAR(control.target(), 0.5, 1e-15);  // the next grid point limits the first increment at the regrown size
  control.converged(kEasy);
  EXPECT_NEAR(control.target(), 0.75, 1e-15);
}

TEST(IncrementController, HardIncrementsDoNotRegrow) {
  IncrementController control;
  control.begin_step(2, 0.0);
  control.failed(false);
  control.failed(false);  // 1/8 of the step
  for (int k = 0; k < 3; ++k) control.converged(kHard);
  EXPECT_NEAR(control.sizes().size, 0.125, 1e-15);
  EXPECT_NEAR(control.sizes().fraction, 0.375, 1e-15);
}

// An increment's size is judged by the corrections before the stick's augmentation rounds, which cost about the
// same at any size: an increment that converged easily and then spent its rounds counts as easy, unless a round was
// abandoned.
TEST(IncrementReport, SizeIsJudgedByTheCorrectionsBeforeTheAugmentationRounds) {
  IncrementReport plain;
  plain.corrections = kHard;
  EXPECT_EQ(plain.size_corrections(), kHard);
  IncrementReport augmented;
  augmented.corrections = 3 * kHard;
  augmented.corrections_before_rounds = kEasy;
  EXPECT_EQ(augmented.size_corrections(), kEasy);
  augmented.kept_converged_round = true;
  EXPECT_EQ(augmented.size_corrections(), 3 * kHard);
}

TEST(IncrementController, ExtrapolatedFailureIsRetriedPlainOnceAndThenNotExtrapolatedInTheStep) {
  IncrementController control;
  control.begin_step(4, 0.1);  // a previous step that loaded the same way
  EXPECT_TRUE(control.may_extrapolate());
  EXPECT_EQ(control.failed(true), Recovery::kPlainRetry);
  EXPECT_TRUE(control.retrying_plain());
  EXPECT_FALSE(control.may_extrapolate());
  EXPECT_NEAR(control.target(), 0.25, 1e-15);  // the same size
  control.converged(kEasy);
  EXPECT_TRUE(control.sizes().extrapolation_failed);
  EXPECT_FALSE(control.may_extrapolate());
  control.begin_step(4, 0.1);  // a new step trusts the predictor again
  EXPECT_TRUE(control.may_extrapolate());
}

TEST(IncrementController, PlainRetryThatFailsCutsBack) {
  IncrementController control;
  control.begin_step(4, 0.1);
  EXPECT_EQ(control.failed(true), Recovery::kPlainRetry);
  EXPECT_EQ(control.failed(false), Recovery::kHalve);
  EXPECT_FALSE(control.retrying_plain());
  EXPECT_NEAR(control.target(), 0.125, 1e-15);
}

TEST(IncrementController, StabilizesAfterTheCutBacksAndStopsAfterASecondSequence) {
  IncrementController control({3, 25, true});
  control.begin_step(4, 0.0);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(control.failed(false), Recovery::kHalve);
  EXPECT_NEAR(control.target(), 0.25 / 8, 1e-15);
  EXPECT_EQ(control.failed(false), Recovery::kStabilize);
  EXPECT_TRUE(control.sizes().stabilized);
  EXPECT_EQ(control.cutbacks(), 0);
  EXPECT_NEAR(control.target(), 0.25 / 4, 1e-15);  // from a quarter of the nominal size
  // The quarter can be halved until max_cutbacks halvings of the nominal size, then nothing is left.
  EXPECT_EQ(control.failed(false), Recovery::kHalve);
  EXPECT_EQ(control.failed(false), Recovery::kStop);
  control.begin_step(4, 0.0);
  EXPECT_FALSE(control.sizes().stabilized);
}

TEST(IncrementController, WithoutTheAutomaticStabilizationTheCutBacksEndTheRun) {
  IncrementController control({2, 25, false});
  control.begin_step(1, 0.0);
  EXPECT_EQ(control.failed(false), Recovery::kHalve);
  EXPECT_EQ(control.failed(false), Recovery::kHalve);
  EXPECT_EQ(control.failed(false), Recovery::kStop);
}

TEST(IncrementController, AlternatingSuccessAndFailureCannotShrinkBelowTheSmallestSize) {
  IncrementController control({2, 25, false});
  control.begin_step(1, 0.0);
  EXPECT_EQ(control.failed(false), Recovery::kHalve);  // 1/2
  control.converged(kHard);
  EXPECT_EQ(control.failed(false), Recovery::kHalve);  // 1/4, the smallest
  control.converged(kHard);
  EXPECT_EQ(control.failed(false), Recovery::kStop);   // one cut-back only, but below 1/4
}

TEST(IncrementController, ResumedStepKeepsItsSizes) {
  IncrementController first;
  first.begin_step(4, 0.0);
  first.failed(false);
  first.converged(kEasy);
  IncrementController resumed;
  resumed.restore(first.sizes());
  resumed.resume_step(4);
  EXPECT_DOUBLE_EQ(resumed.target(), first.target());
  EXPECT_EQ(resumed.sizes().converged_increments, 1);
}

}  // namespace
}  // namespace strandfem
