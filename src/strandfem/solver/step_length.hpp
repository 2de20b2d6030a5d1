// Step length of a Newton correction: the interactions' step control, then backtracking while the residual rises.
#pragma once
#include <functional>

#include "strandfem/solver/convergence_test.hpp"

namespace strandfem {

// The iterate at start + alpha x correction.
struct StepTrial {
  double alpha = 1;
  double correction2 = 0;  // squared norm of the motion taken (rotations weighted by the mean element length)
  ResidualCheck check;
};

struct StepLength {
  StepTrial accepted;
  double full_correction2 = 0;  // squared norm of the whole correction
  bool limited = false;         // the step control shortened it
};

// try_step(alpha) moves the iterate and measures it. admissible(), asked after the full correction has been tried:
// the largest fraction the interactions allow (1: no limit). Then, while the residual stays above current_relative,
// the step is halved at most `cuts` times; the last try is kept either way.
StepLength choose_step_length(const std::function<StepTrial(double)>& try_step, const std::function<double()>& admissible,
                              double current_relative, int cuts);

}  // namespace strandfem
