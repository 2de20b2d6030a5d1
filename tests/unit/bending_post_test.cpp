// Requirement: the closed-form tensioned-beam deflections (eqs. 3.1, 3.2) have the right limits and agree
// with each other; the equivalent EI inverts eq. 3.1; hysteresis loops give the area of a known polygon.
#include "strandfem/post/bending.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

namespace strandfem {
namespace {

TEST(TensionedBeam, MidspanOfTheCurveIsEq31AndSymmetricLimitsHold) {
  const double V = 40000, T = 280000, L = 1000;
  for (const double EI : {82.7e6, 6357.8e6}) {  // S32 EImin and EImax (paper: 82.7 and 6357.8 N m^2)
    EXPECT_NEAR(tensioned_beam_deflection(V, T, EI, L, 0.5 * L), tensioned_beam_midspan_deflection(V, T, EI, L),
                1e-9 * L);
    EXPECT_NEAR(tensioned_beam_deflection(V, T, EI, L, 0.0), 0.0, 1e-12);
  }
  // No tension: Euler-Bernoulli clamped-clamped V L^3 / (192 EI) (k >> L).
  const double EI = 1e9, small_T = 1e-3;
  EXPECT_NEAR(tensioned_beam_midspan_deflection(V, small_T, EI, L), V * L * L * L / (192 * EI), 1e-4 * V * L * L * L / (192 * EI));
  EXPECT_NEAR(tensioned_beam_deflection(V, small_T, EI, L, 0.25 * L), V * std::pow(0.25 * L, 2) * (3 * L - L) / (48 * EI),
              1e-4 * V * L * L * L / (192 * EI));
  // No bending stiffness: the string V L / (4T); and a very slender strand stays finite.
  EXPECT_NEAR(tensioned_beam_midspan_deflection(V, T, 1e-6, L), V * L / (4 * T), 1e-6 * V * L / (4 * T));
  EXPECT_NEAR(tensioned_beam_deflection(V, T, 1e-6, L, 0.25 * L), V * 0.25 * L / (2 * T), 1e-6 * V * L / T);
  // S32 case 4 (T = 280 kN, V = 40 kN): EImin gives the larger deflection.
  EXPECT_GT(tensioned_beam_midspan_deflection(V, T, 82.7e6, L), tensioned_beam_midspan_deflection(V, T, 6357.8e6, L));
}

// The Timoshenko form: eq. 3.2 as the shear stiffness grows, the clamped-clamped Timoshenko beam (bending plus
// V x / (2S)) without tension, and next to a clamp above eq. 3.2 by most of V x / (2S) (the tension takes the
// rest: the bending part falls by (1 - T/S)^2).
TEST(TensionedBeam, TimoshenkoFormHasBothLimits) {
  const double V = 40000, T = 280000, L = 1000, EI = 82.7e6;
  for (const double x : {5.0, 100.0, 500.0})
    EXPECT_NEAR(tensioned_timoshenko_deflection(V, T, EI, 1e18, L, x), tensioned_beam_deflection(V, T, EI, L, x),
                1e-9 * tensioned_beam_deflection(V, T, EI, L, x));
  const double S = 3.7e7, stiff = 1e9, small_T = 1e-3;
  const double euler_bernoulli_midspan = V * L * L * L / (192 * stiff);
  for (const double x : {5.0, 250.0, 500.0}) {
    const double timoshenko = V * x * x * (3 * L - 4 * x) / (48 * stiff) + V * x / (2 * S);
    EXPECT_NEAR(tensioned_timoshenko_deflection(V, small_T, stiff, S, L, x), timoshenko, 1e-4 * euler_bernoulli_midspan);
  }
  const double shear_part = tensioned_timoshenko_deflection(V, T, EI, S, L, 5.0) - tensioned_beam_deflection(V, T, EI, L, 5.0);
  EXPECT_GT(shear_part, 0.75 * V * 5.0 / (2 * S));
  EXPECT_LT(shear_part, V * 5.0 / (2 * S));
}

// The bounds check counts the nodes between the curves, leaves out the clamped end nodes and those inside the
// clamp-edge offset, and reports the worst excess and shortfall with where they lie.
TEST(TensionedBeam, CurveBoundsCheckCountsAndLocatesTheWorstNodes) {
  const std::vector<CurveSample> curve = {
      {0.0, 0.0, 0.0, 0.0},       // clamped end node: left out
      {5.0, 0.0505, 0.01, 0.05},  // 1 % above
      {10.0, 0.15, 0.04, 0.16},   // within
      {20.0, 0.5, 0.12, 0.6},     // within
      {30.0, 0.26, 0.28, 1.2},    // 0.02 below
      {40.0, 2.0, 0.5, 1.99},     // 0.01 above: the larger excess in mm, the smaller in per cent
  };
  const CurveBoundsCheck all = check_curve_bounds(curve);
  EXPECT_EQ(all.nodes, 5);
  EXPECT_EQ(all.within, 2);
  EXPECT_NEAR(all.largest_excess, 0.01, 1e-12);
  EXPECT_EQ(all.largest_excess_x, 40.0);
  EXPECT_NEAR(all.largest_excess_relative, 0.01 / 1.99, 1e-12);
  EXPECT_NEAR(all.largest_shortfall, 0.02, 1e-12);
  EXPECT_EQ(all.largest_shortfall_x, 30.0);
  const CurveBoundsCheck beyond = check_curve_bounds(curve, 10.0);
  EXPECT_EQ(beyond.nodes, 4);
  EXPECT_EQ(beyond.within, 2);
  const CurveBoundsCheck inner = check_curve_bounds({curve[2], curve[3]}, 10.0);
  EXPECT_EQ(inner.within, inner.nodes);
  EXPECT_EQ(inner.largest_excess, 0.0);
  EXPECT_EQ(inner.largest_shortfall, 0.0);
}

// The rise from the load point of eq. 3.2's own curve, sampled every 5 mm, is the closed form's y(L/2) - y(L/2 - d)
// to the linear interpolation's error; an unsymmetric curve gives the mean of its two sides.
TEST(TensionedBeam, RiseFromTheLoadPointOfEq32AndOfAnUnsymmetricCurve) {
  const double V = 5000, T = 40000, L = 1000, EI = 82.7e6;  // S32 case 1, EImin
  std::vector<DeflectionPoint> curve;
  for (int i = 0; i <= 200; ++i) {
    const double z = 5.0 * i;
    curve.push_back({z, tensioned_beam_deflection(V, T, EI, L, std::min(z, L - z))});
  }
  for (const double d : {45.0, 150.0, 152.5}) {
    const double exact = tensioned_beam_deflection(V, T, EI, L, 0.5 * L) - tensioned_beam_deflection(V, T, EI, L, 0.5 * L - d);
    EXPECT_NEAR(rise_from_load_point(curve, 0.5 * L, d), exact, 1e-3 * exact) << d;
  }
  const std::vector<DeflectionPoint> tilted = {{0, 0}, {10, 1}, {20, 4}, {30, 3}, {40, 0}};
  EXPECT_DOUBLE_EQ(rise_from_load_point(tilted, 20, 10), 4 - 0.5 * (1 + 3));
  EXPECT_DOUBLE_EQ(rise_from_load_point(tilted, 20, 5), 4 - 0.5 * (2.5 + 3.5));
  EXPECT_DOUBLE_EQ(rise_from_load_point(tilted, 20, 30), 4.0);  // both sides beyond the ends take the end points
}

TEST(TensionedBeam, EquivalentStiffnessInvertsEq31) {
  const double T = 280000, L = 1000, V = 40000;
  for (const double EI : {82.7e6, 1e9, 6357.8e6}) {
    const double y = tensioned_beam_midspan_deflection(V, T, EI, L);
    EXPECT_NEAR(equivalent_bending_stiffness(y / V, T, L), EI, 1e-8 * EI);
  }
  EXPECT_EQ(equivalent_bending_stiffness(L / (4 * T), T, L), 0.0);
  EXPECT_TRUE(std::isinf(equivalent_bending_stiffness(0.0, T, L)));
}

TEST(Hysteresis, ParallelogramLoopAreaStiffnessAndSteadiness) {
  // Two identical cycles from (0, 0):
  // out (0,0) -> (1,10) -> (3,12); back (3,12) -> (2,2) -> (0,0). Its area: triangles (0,0),(1,10),(3,12) and (0,0),(3,12),(2,2), 9 each.
  // Friction dissipates 0.5 N mm during the tension ramp, then 7 N mm in the first cycle and 5 in the second.
  std::vector<LoadDeflectionPoint> history = {{0, false, 0, 0, 500, 0.5}};  // end of the tension ramp
  double dissipated = 0.5;
  for (int cycle = 1; cycle <= 2; ++cycle) {
    const double per_increment = cycle == 1 ? 1.75 : 1.25;
    for (const auto& [returning, load, deflection, tension] :
         {std::make_tuple(false, 10.0, 1.0, 500.0), std::make_tuple(false, 12.0, 3.0, 510.0), std::make_tuple(true, 2.0, 2.0, 505.0),
          std::make_tuple(true, 0.0, 0.0, 500.0)})
      history.push_back({cycle, returning, load, deflection, tension, dissipated += per_increment});
  }
  const auto loops = hysteresis_loops(history);
  ASSERT_EQ(loops.size(), 2u);
  for (const auto& loop : loops) {
    EXPECT_NEAR(loop.area, 18.0, 1e-12);
    EXPECT_DOUBLE_EQ(loop.peak_load, 12);
    EXPECT_DOUBLE_EQ(loop.peak_deflection, 3);
    EXPECT_DOUBLE_EQ(loop.peak_tension, 510);
    EXPECT_DOUBLE_EQ(loop.secant_stiffness, 4);
    EXPECT_DOUBLE_EQ(loop.loading_tangent, 10);
    EXPECT_DOUBLE_EQ(loop.unloading_tangent, 10);
  }
  EXPECT_NEAR(loops[0].friction_dissipation, 7.0, 1e-12);
  EXPECT_NEAR(loops[1].friction_dissipation, 5.0, 1e-12);
  EXPECT_TRUE(loop_is_steady(loops[0], loops[1], 0.01));
  HysteresisLoop larger = loops[1];
  larger.area *= 1.1;
  EXPECT_FALSE(loop_is_steady(loops[0], larger, 0.05));
  // The changes against the previous cycle: friction's work 7 -> 5 is -2/7 of the larger; the area 18 -> 19.8 is
  // +1.8/19.8; a peak 0.3 mm further is +0.3 over the larger travel, 3.3 mm.
  EXPECT_NEAR(cycle_change(loops[0], loops[1]).friction_dissipation, -2.0 / 7.0, 1e-12);
  EXPECT_NEAR(cycle_change(loops[0], loops[1]).area, 0.0, 1e-12);
  EXPECT_NEAR(cycle_change(loops[0], larger).area, 1.8 / 19.8, 1e-12);
  HysteresisLoop further = loops[1];
  further.peak_deflection += 0.3;
  EXPECT_NEAR(cycle_change(loops[0], further).peak_deflection, 0.3 / 3.3, 1e-12);
  EXPECT_TRUE(loop_is_steady(loops[0], further, 0.1));
  EXPECT_FALSE(loop_is_steady(loops[0], further, 0.09));
  // The return loop (cycle 1's return half and cycle 2's loading half, peak to peak) of two identical cycles is
  // the loop itself; friction's work from peak 1 (4 N mm) to peak 2 (10 N mm).
  EXPECT_FALSE(loops[0].has_return_loop);
  ASSERT_TRUE(loops[1].has_return_loop);
  EXPECT_NEAR(loops[1].return_loop_area, 18.0, 1e-12);
  EXPECT_NEAR(loops[1].return_loop_friction_dissipation, 6.0, 1e-12);
  // An incomplete last cycle (no return half) gives no loop.
  history.push_back({3, false, 10, 1});
  EXPECT_EQ(hysteresis_loops(history).size(), 2u);
}

TEST(Hysteresis, ReturnLoopLeavesOutTheFirstLoadingsSet) {
  // Cycle 1 locks in a set of 1 mm: out (0,0) -> (1,10) -> (4,12), back -> (3,2) -> (1,0); its loop, polygon
  // (0,0),(1,10),(4,12),(3,2),(1,0), has area 29. Cycle 2 repeats the parallelogram of area 18 from (1,0). The
  // return loop of cycle 2, (4,12),(3,2),(1,0),(2,10),(4,12), is that parallelogram: the 11 N mm of the set are
  // in cycle 1's area only.
  std::vector<LoadDeflectionPoint> history = {{0, false, 0, 0, 500, 0}};
  const std::vector<std::tuple<int, bool, double, double>> points = {
      {1, false, 10, 1}, {1, false, 12, 4}, {1, true, 2, 3}, {1, true, 0, 1},
      {2, false, 10, 2}, {2, false, 12, 4}, {2, true, 2, 3}, {2, true, 0, 1}};
  double dissipated = 0;
  for (const auto& [cycle, returning, load, deflection] : points)
    history.push_back({cycle, returning, load, deflection, 500, dissipated += 1});
  const auto loops = hysteresis_loops(history);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_NEAR(loops[0].area, 29.0, 1e-12);
  EXPECT_NEAR(loops[1].area, 18.0, 1e-12);
  ASSERT_TRUE(loops[1].has_return_loop);
  EXPECT_NEAR(loops[1].return_loop_area, 18.0, 1e-12);
  EXPECT_NEAR(loops[1].return_loop_friction_dissipation, 4.0, 1e-12);  // from point 2 (peak 1) to point 6 (peak 2)
  // A cycle that does not start where the previous one ended (another step between them) has none.
  history.insert(history.begin() + 5, LoadDeflectionPoint{0, false, 0, 1, 500, 4});
  EXPECT_FALSE(hysteresis_loops(history)[1].has_return_loop);
}

}  // namespace
}  // namespace strandfem
