// The increment controller of a load step: the next increment's size, regrowth, and what to try after a failure.
#pragma once

namespace strandfem {

// What the controller does after a failed attempt, tried in this order.
enum class Recovery {
  kPlainRetry,  // the same size again, from the plain predictor instead of the extrapolated one
  kHalve,       // a cut-back: half the size
  kStabilize,   // the automatic stabilization, on for the rest of the step, from a quarter of the nominal size
  kStop         // nothing left to try
};

struct IncrementLimits {
  int max_cutbacks = 8;                  // SolverOptions::max_cutbacks
  int max_iterations = 25;               // SolverOptions::max_iterations (sets what counts as an easy increment)
  bool automatic_stabilization = true;   // SolverOptions::automatic_stabilization
};

// Sizes are fractions of the step (0..1). The sizes survive checkpoints (sizes()); a failed attempt's cut-back
// count and plain retry do not need to, since a checkpoint follows a converged increment.
class IncrementController {
 public:
  struct Sizes {
    double fraction = 0;          // converged load fraction of the step
    double size = 0;              // next increment's size
    double largest_size = 0;      // cap on the size after a failure, raised again by easy increments
    double last_size = 0;         // last converged increment (0: none, so no extrapolation)
    int easy_at_cap = 0;          // easy increments at the cap since it was set
    int converged_increments = 0;
    bool extrapolation_failed = false;  // a plain retry converged where extrapolation failed: none for the step
    bool stabilized = false;      // the automatic stabilization is on for the rest of the step
  };

  explicit IncrementController(IncrementLimits limits = {}) : limits_(limits) {}

  // A new step of `increments` nominal increments; carried_last_size: the last increment of a previous step that
  // loaded the same way, in this step's fraction units (0: none).
  void begin_step(int increments, double carried_last_size);
  // Goes on with a step begun earlier (its sizes restored from a checkpoint by restore()).
  void resume_step(int increments);
  void restore(const Sizes& sizes) { s_ = sizes; }

  bool step_done() const { return s_.fraction >= 1.0 - 1e-12; }
  double nominal() const { return nominal_; }
  // Where the next attempt ends: one size on, never past the next point of the nominal grid (k / increments), so
  // that after cut-backs the increments land on the load levels the case asked for again.
  double target() const;
  int cutbacks() const { return cutbacks_; }
  // A cut-back has capped the sizes below the nominal one and they have not grown back yet.
  bool recovering() const { return s_.largest_size < nominal_ * (1.0 - 1e-9); }
  bool retrying_plain() const { return plain_retry_; }
  // The next attempt may start from the extrapolated predictor: there is a last increment to go by, and neither a
  // failure in this increment nor an earlier plain retry in this step says it misleads.
  bool may_extrapolate() const { return s_.last_size > 0 && cutbacks_ == 0 && !plain_retry_ && !s_.extrapolation_failed; }

  // The attempt to target() converged in this many Newton corrections.
  void converged(int corrections);
  // The attempt to target() failed; extrapolated: it started from the extrapolated predictor.
  Recovery failed(bool extrapolated);

  const Sizes& sizes() const { return s_; }

 private:
  IncrementLimits limits_;
  double nominal_ = 1;
  Sizes s_;
  int cutbacks_ = 0;
  bool plain_retry_ = false;
};

}  // namespace strandfem
