// Requirement: load steps expand into ramps; a cyclic step goes to its targets and back to the totals
// before it, n times, and records where each ramp comes from.
#include "strandfem/analysis/load_protocol.hpp"

#include <gtest/gtest.h>

namespace strandfem {
namespace {

NodalAction force(int node, int component, double value) { return {NodalAction::kForce, node, component, value}; }

TEST(LoadProtocol, PlainStepsAreOneRampEach) {
  const std::vector<LoadStep> steps = {{"pull", 20, {{NodalAction::kMotion, 4, kUz, 0.5}}, 0},
                                       {"hold", 3, {}, 0}};
  const auto ramps = expand_load_steps(steps);
  ASSERT_EQ(ramps.size(), 2u);
  EXPECT_EQ(ramps[0].name, "pull");
  EXPECT_EQ(ramps[0].increments, 20);
  EXPECT_EQ(ramps[1].origin.step, 1);
  EXPECT_EQ(ramps[1].origin.cycle, 0);
  EXPECT_TRUE(ramps[1].actions.empty());
}

TEST(LoadProtocol, CyclesGoOutAndBackToTheTotalsBeforeTheStep) {
  // Tension to 40 kN, then a transverse load 0 -> 1 kN -> 0 three times while the tension is held.
  const std::vector<LoadStep> steps = {{"tension", 20, {force(7, kUz, 40000)}, 0},
                                       {"bend", 10, {force(3, kUy, 1000)}, 3},
                                       {"release", 5, {force(7, kUz, 0)}, 0}};
  const auto ramps = expand_load_steps(steps);
  ASSERT_EQ(ramps.size(), 1u + 6u + 1u);
  for (int cycle = 1; cycle <= 3; ++cycle) {
    const LoadRamp& out = ramps[2 * cycle - 1];
    const LoadRamp& back = ramps[2 * cycle];
    EXPECT_EQ(out.origin.step, 1);
    EXPECT_EQ(out.origin.cycle, cycle);
    EXPECT_FALSE(out.origin.returning);
    EXPECT_TRUE(back.origin.returning);
    EXPECT_EQ(out.increments, 10);
    ASSERT_EQ(out.actions.size(), 1u);
    ASSERT_EQ(back.actions.size(), 1u);
    EXPECT_DOUBLE_EQ(out.actions[0].value, 1000);
    EXPECT_DOUBLE_EQ(back.actions[0].value, 0);  // the transverse load had no total before the step
    EXPECT_EQ(back.actions[0].node, 3);
    EXPECT_EQ(back.actions[0].component, kUy);
  }
  EXPECT_EQ(ramps[1].name, "bend cycle 1 out");
  EXPECT_EQ(ramps[6].name, "bend cycle 3 back");
  EXPECT_EQ(ramps[7].origin.step, 2);
}

TEST(LoadProtocol, CyclesBetweenTwoValuesReturnToTheEarlierTotal) {
  // Tension cycles between 20 kN (the total before) and 40 kN.
  const std::vector<LoadStep> steps = {{"preload", 10, {force(7, kUz, 20000)}, 0},
                                       {"cycle", 4, {force(7, kUz, 40000)}, 2}};
  const auto ramps = expand_load_steps(steps);
  ASSERT_EQ(ramps.size(), 5u);
  EXPECT_DOUBLE_EQ(ramps[1].actions[0].value, 40000);
  EXPECT_DOUBLE_EQ(ramps[2].actions[0].value, 20000);
  EXPECT_DOUBLE_EQ(ramps[3].actions[0].value, 40000);
  EXPECT_DOUBLE_EQ(ramps[4].actions[0].value, 20000);
}

}  // namespace
}  // namespace strandfem
