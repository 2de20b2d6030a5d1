// Requirement: a Newton correction is shortened by the interactions' step control, then halved while it raises the
// residual, at most the allowed number of times.
#include "strandfem/solver/step_length.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace strandfem {
namespace {

// A residual that falls to zero at alpha = a0 and rises on either side; records the fractions tried.
struct Valley {
  double a0;
  std::vector<double> tried;
  StepTrial operator()(double alpha) {
    tried.push_back(alpha);
    StepTrial t;
    t.alpha = alpha;
    t.correction2 = alpha * alpha;
    t.check.relative = std::abs(alpha - a0);
    return t;
  }
};

TEST(StepLength, FullCorrectionKeptWhenItLowersTheResidual) {
  Valley valley{0.9, {}};
  const StepLength s = choose_step_length(std::ref(valley), [] { return 1.0; }, 0.5, 4);
  EXPECT_EQ(valley.tried, (std::vector<double>{1.0}));
  EXPECT_DOUBLE_EQ(s.accepted.alpha, 1.0);
  EXPECT_FALSE(s.limited);
}

TEST(StepLength, HalvedWhileTheResidualRises) {
  Valley valley{0.2, {}};
  // Full step: 0.8, above the current 0.3; 0.5 leaves 0.3 (not below... equal passes), so the search stops there.
  const StepLength s = choose_step_length(std::ref(valley), [] { return 1.0; }, 0.3, 4);
  EXPECT_EQ(valley.tried, (std::vector<double>{1.0, 0.5}));
  EXPECT_DOUBLE_EQ(s.accepted.alpha, 0.5);
  EXPECT_DOUBLE_EQ(s.full_correction2, 1.0);
}

TEST(StepLength, AtMostTheAllowedCutsAndTheLastTryKept) {
  Valley valley{-1.0, {}};  // every step raises the residual above 0.5
  const StepLength s = choose_step_length(std::ref(valley), [] { return 1.0; }, 0.5, 3);
  EXPECT_EQ(valley.tried, (std::vector<double>{1.0, 0.5, 0.25, 0.125}));
  EXPECT_DOUBLE_EQ(s.accepted.alpha, 0.125);
  Valley none{-1.0, {}};
  EXPECT_DOUBLE_EQ(choose_step_length(std::ref(none), [] { return 1.0; }, 0.5, 0).accepted.alpha, 1.0);
}

TEST(StepLength, StepControlShortensBeforeTheSearch) {
  Valley valley{0.1, {}};
  const StepLength s = choose_step_length(std::ref(valley), [] { return 0.4; }, 0.25, 4);
  // 1.0 (full, measured), 0.4 (admissible: 0.3 left, above 0.25), 0.2 (0.1 left).
  EXPECT_EQ(valley.tried, (std::vector<double>{1.0, 0.4, 0.2}));
  EXPECT_TRUE(s.limited);
  EXPECT_DOUBLE_EQ(s.accepted.alpha, 0.2);
  EXPECT_DOUBLE_EQ(s.full_correction2, 1.0);
  EXPECT_NEAR(s.accepted.correction2, 0.04, 1e-15);
}

}  // namespace
}  // namespace strandfem
