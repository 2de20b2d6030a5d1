// Requirement: a Newton attempt is diverging when its residual, eight corrections after the interactions last changed
// their states, is above where those corrections started (after a first correction that raised it, from there); a
// contact round restarts the count; max_iterations corrections in a row end the attempt.
#include "strandfem/solver/attempt_budget.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace strandfem {
namespace {

// Loop passes as solve_increment makes them: the check at each iterate, then one pass on.
int first_diverging_pass(AttemptBudget& budget, const std::vector<double>& residuals) {
  for (std::size_t k = 0; k < residuals.size(); ++k) {
    if (budget.diverging(residuals[k])) return static_cast<int>(k);
    budget.next();
  }
  return -1;
}

// Cardinal's aluminum layers at mu 0.9 under bending: the load step's correction leaves 0.057 (from 0.0042), the
// next one closes contacts its tangent did not know (1.27), and the residual is still above 0.057 eight corrections on.
TEST(AttemptBudget, DivergingWhenEightCorrectionsAfterTheFirstAreStillAboveIt) {
  AttemptBudget budget(25, 0.0042);
  EXPECT_FALSE(budget.diverging(0.0042));
  budget.next();
  budget.first_correction_left(0.057);
  const std::vector<double> after_first{0.057, 1.27, 1.15, 0.79, 1.04, 0.99, 0.72, 0.53};
  EXPECT_EQ(first_diverging_pass(budget, after_first), 7) << "the eighth pass after the predictor";
}

TEST(AttemptBudget, AFallingResidualIsNotDivergingAndARoundRestartsTheCount) {
  AttemptBudget budget(25, 1.0);
  EXPECT_EQ(first_diverging_pass(budget, std::vector<double>(12, 0.9)), -1) << "below the predictor's residual";
  budget.restart(0.01);
  EXPECT_EQ(first_diverging_pass(budget, std::vector<double>(8, 0.02)), -1) << "seven passes since the round";
  EXPECT_TRUE(budget.diverging(0.02));
  EXPECT_FALSE(budget.diverging(0.009));
}

TEST(AttemptBudget, FirstCorrectionBelowThePredictorKeepsThePredictorAsReference) {
  AttemptBudget budget(25, 0.5);
  budget.next();
  budget.first_correction_left(0.1);
  for (int k = 1; k < AttemptBudget::kDivergenceWindow; ++k) budget.next();
  EXPECT_FALSE(budget.diverging(0.4));
  EXPECT_TRUE(budget.diverging(0.6));
}

TEST(AttemptBudget, SpentAfterMaxIterationsPassesSinceTheLastRound) {
  AttemptBudget budget(3, 1.0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_FALSE(budget.spent());
    budget.next();
  }
  EXPECT_TRUE(budget.spent());
  budget.restart(1.0);
  EXPECT_FALSE(budget.spent());
}

}  // namespace
}  // namespace strandfem
