// When a Newton attempt gives up: corrections counted from the interactions' last change of states, and the
// residual they must come back below (docs/theory.md, "Increment control").
#pragma once
#include <algorithm>

namespace strandfem {

class AttemptBudget {
 public:
  // An attempt whose residual, this many corrections after the last change, is above the residual it had there is
  // diverging: it is cut back at once rather than after max_iterations.
  static constexpr int kDivergenceWindow = 8;

  // start_residual: the predictor's relative residual.
  AttemptBudget(int max_iterations, double start_residual) : max_iterations_(max_iterations), round_start_(start_residual) {}

  // One more pass of Newton's loop: a correction, or a round of changed states.
  void next() { ++since_change_; }
  // The interactions changed their states (a contact round) and the residual is now `residual`: count afresh.
  void restart(double residual) {
    since_change_ = 0;
    round_start_ = residual;
  }
  // The attempt's first correction carries the load step and may raise the residual: the corrections after it are
  // measured from where it left the attempt when that is higher.
  void first_correction_left(double residual) { round_start_ = std::max(round_start_, residual); }
  bool diverging(double residual) const { return since_change_ >= kDivergenceWindow && residual > round_start_; }
  bool spent() const { return since_change_ >= max_iterations_; }

 private:
  int max_iterations_;
  double round_start_;
  int since_change_ = 0;
};

}  // namespace strandfem
