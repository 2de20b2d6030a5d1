// Requirement: an increment cut below the nominal size measures its corrections against a nominal increment's motion.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace strandfem
