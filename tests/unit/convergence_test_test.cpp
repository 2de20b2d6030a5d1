// Requirement: the force test measures residuals against the step's loads and meets every applied load on its own.
#include "strandfem/solver/convergence_test.hpp"

#include <gtest/gtest.h>

namespace strandfem {
namespace {

// Node 0 clamped (its internal forces are reactions), node 1 free with equations 0..5.
DofMap clamped_and_free() {
  DofMap dofs;
  dofs.tie_of = {-1, -1};
  dofs.equation = {{-1, -1, -1, -1, -1, -1}, {0, 1, 2, 3, 4, 5}};
  dofs.equation_count = 6;
  return dofs;
}

SolverOptions tolerances() {
  SolverOptions options;
  options.force_tolerance = options.moment_tolerance = 0.005;
  options.load_tolerance = 0.001;
  return options;
}

TEST(ConvergenceTest, LoadNormsAreAppliedLoadsAtFreeDofsAndReactionsElsewhere) {
  const ConvergenceTest test(tolerances(), 10.0, 0.0, 0.0);
  std::vector<double> internal(12, 0.0), external(12, 0.0);
  internal[2] = -3.0, internal[1] = 4.0;  // reactions at the clamp
  external[6 + 2] = 12.0;                 // applied at the free node
  internal[6 + 2] = 11.0;                 // not the load norm: the free node's own internal force
  internal[5] = 2.0;                      // a reaction moment
  const LoadReference norms = test.load_norms(clamped_and_free(), internal, external);
  EXPECT_DOUBLE_EQ(norms.force, 13.0);
  EXPECT_DOUBLE_EQ(norms.moment, 2.0);
}

TEST(ConvergenceTest, ReleasedStrandIsMeasuredAgainstTheLoadItCarriedInTheStep) {
  ConvergenceTest test(tolerances(), 10.0, 1e-9, 0.0);
  const DofMap dofs = clamped_and_free();
  std::vector<double> internal(12, 0.0), external(12, 0.0), rhs(6);
  internal[2] = 2.0;       // a reaction of 2 N left at the end of a release
  internal[6 + 0] = 1.0;   // a residual of 1 N at the free node
  // Alone, the state's own loads make the residual half of the reference: no convergence.
  test.begin_step({0.0, 0.0});
  ResidualCheck check = test.measure(dofs, internal, external, rhs);
  EXPECT_NEAR(check.relative, 0.5, 1e-12);
  EXPECT_FALSE(check.forces_ok);
  EXPECT_DOUBLE_EQ(rhs[0], -1.0);
  // The step began under 1000 N: 1 N of residual is 0.1 % of it.
  test.begin_step({1000.0, 0.0});
  check = test.measure(dofs, internal, external, rhs);
  EXPECT_NEAR(check.relative, 1e-3, 1e-12);
  EXPECT_TRUE(check.forces_ok);
  EXPECT_DOUBLE_EQ(check.state.force, 2.0);
}

TEST(ConvergenceTest, StepReferenceKeepsTheLargestConvergedLoads) {
  ConvergenceTest test(tolerances(), 10.0, 0.0, 0.0);
  test.begin_step({5.0, 1.0});
  test.accept({20.0, 0.5});
  test.accept({3.0, 7.0});
  EXPECT_DOUBLE_EQ(test.step_reference().force, 20.0);
  EXPECT_DOUBLE_EQ(test.step_reference().moment, 7.0);
  test.begin_step({2.0, 0.0});  // a new step starts from its own first state
  EXPECT_DOUBLE_EQ(test.step_reference().force, 2.0);
}

TEST(ConvergenceTest, SmallAppliedLoadIsMetOnItsOwnBesideALargeTension) {
  ConvergenceTest test(tolerances(), 10.0, 0.0, 0.0);
  const DofMap dofs = clamped_and_free();
  std::vector<double> internal(12, 0.0), external(12, 0.0), rhs(6);
  internal[2] = -20000.0;   // the clamp holds 20 kN of tension
  external[6 + 1] = 50.0;   // a 50 N transverse load at the free node, its largest value in the step
  test.set_applied_loads({{1, 50.0, false}});
  // The node carries 46.3 N of it: 3.7 N of residual is 2e-4 of the tension, but 7.4 % of the load.
  internal[6 + 1] = 46.3;
  ResidualCheck check = test.measure(dofs, internal, external, rhs);
  EXPECT_LT(check.relative, 0.005);
  EXPECT_NEAR(check.worst_load, 3.7 / 0.05, 1e-9);
  EXPECT_FALSE(check.forces_ok);
  // Met to 0.04 N (0.08 %): converged.
  internal[6 + 1] = 49.96;
  check = test.measure(dofs, internal, external, rhs);
  EXPECT_LE(check.worst_load, 1.0);
  EXPECT_TRUE(check.forces_ok);
}

TEST(ConvergenceTest, AppliedLoadAllowanceNeverFallsBelowRoundOff) {
  ConvergenceTest test(tolerances(), 10.0, 0.0, 0.5);
  const DofMap dofs = clamped_and_free();
  std::vector<double> internal(12, 0.0), external(12, 0.0), rhs(6);
  internal[2] = -20000.0;
  external[6 + 3] = 10.0;                  // a 10 N mm moment, 0.01 N mm of allowance by the load tolerance
  test.set_applied_loads({{3, 10.0, true}});
  internal[6 + 3] = 10.0 - 2.0;            // within the round-off of moments, 0.5 N x 10 mm
  EXPECT_TRUE(test.measure(dofs, internal, external, rhs).forces_ok);
  internal[6 + 3] = 10.0 - 6.0;
  EXPECT_FALSE(test.measure(dofs, internal, external, rhs).forces_ok);
}

}  // namespace
}  // namespace strandfem

namespace strandfem {
namespace {

ResidualCheck passing_forces(double relative, double load_norm) {
  ResidualCheck check;
  check.relative = relative;
  check.forces_ok = true;
  check.state.force = load_norm;
  return check;
}

TEST(ConvergenceDecision, CorrectionSmallAgainstTheIncrementsMotion) {
  const ConvergenceTest test(tolerances(), 10.0, 0.0, 0.0);  // displacement tolerance 0.005
  // A correction of 0.004 of the increment's motion passes, 0.006 does not.
  EXPECT_TRUE(test.decide(passing_forces(1e-3, 100), {false, 2, 0.004 * 0.004, 1.0, 100}).converged);
  const Convergence wide = test.decide(passing_forces(1e-3, 100), {false, 2, 0.006 * 0.006, 1.0, 100});
  EXPECT_FALSE(wide.converged);
  // Nothing passes without the force test.
  ResidualCheck failing = passing_forces(1e-3, 100);
  failing.forces_ok = false;
  EXPECT_FALSE(test.decide(failing, {false, 2, 0.0, 1.0, 100}).converged);
}

TEST(ConvergenceDecision, PredictorOnlyFarWithinTheTolerance) {
  const ConvergenceTest test(tolerances(), 10.0, 0.0, 0.0);
  EXPECT_FALSE(test.decide(passing_forces(1e-4, 100), {true, 0, 0.0, 0.0, 0}).converged);  // 2 % of the tolerance
  EXPECT_TRUE(test.decide(passing_forces(4e-6, 100), {true, 0, 0.0, 0.0, 0}).converged);   // 8e-4 of it
}

TEST(ConvergenceDecision, ForceTestAloneAfterSeveralCorrectionsWithSettledLoads) {
  ConvergenceTest test(tolerances(), 10.0, 0.0, 0.0);
  test.begin_step({100.0, 0.0});
  const double wandering = 0.05 * 0.05;  // corrections of 5 % of the increment's motion: no displacement test
  // Within a tenth of the tolerance, after 4 corrections, the load norm moved by 1e-4 of it: accepted, force only.
  const Convergence settled = test.decide(passing_forces(4e-4, 100.0), {false, 4, wandering, 1.0, 100.01});
  EXPECT_TRUE(settled.converged);
  EXPECT_TRUE(settled.force_only);
  // Too early, not far enough within the tolerance, or loads still moving (0.3 %): not accepted.
  EXPECT_FALSE(test.decide(passing_forces(4e-4, 100.0), {false, 3, wandering, 1.0, 100.01}).converged);
  EXPECT_FALSE(test.decide(passing_forces(6e-4, 100.0), {false, 4, wandering, 1.0, 100.01}).converged);
  EXPECT_FALSE(test.decide(passing_forces(4e-4, 100.0), {false, 4, wandering, 1.0, 100.3}).converged);
}

}  // namespace
}  // namespace strandfem
