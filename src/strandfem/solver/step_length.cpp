#include "strandfem/solver/step_length.hpp"

namespace strandfem {

StepLength choose_step_length(const std::function<StepTrial(double)>& try_step, const std::function<double()>& admissible,
                              double current_relative, int cuts) {
  StepLength result;
  result.accepted = try_step(1.0);
  result.full_correction2 = result.accepted.correction2;
  const double fraction = admissible();
  if (fraction < 1) {
    result.limited = true;
    result.accepted = try_step(fraction);
  }
  for (int cut = 0; cut < cuts && !(result.accepted.check.relative <= current_relative); ++cut)
    result.accepted = try_step(0.5 * result.accepted.alpha);
  return result;
}

}  // namespace strandfem
