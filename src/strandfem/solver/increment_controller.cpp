#include "strandfem/solver/increment_controller.hpp"

#include <algorithm>
#include <cmath>

namespace strandfem {
namespace {
constexpr int kEasyIncrementsBeforeRegrowth = 3;
constexpr double kStabilizedRestartSize = 0.25;  // of the nominal increment
}  // namespace

void IncrementController::begin_step(int increments, double carried_last_size) {
  nominal_ = 1.0 / std::max(1, increments);
  s_ = Sizes{};
  s_.size = s_.largest_size = nominal_;
  s_.last_size = carried_last_size;
  cutbacks_ = 0;
  plain_retry_ = false;
}

void IncrementController::resume_step(int increments) {
  nominal_ = 1.0 / std::max(1, increments);
  cutbacks_ = 0;
  plain_retry_ = false;
}

double IncrementController::target() const {
  const double next_nominal = nominal_ * (std::floor(s_.fraction / nominal_ + 1e-9) + 1.0);
  return std::min({1.0, s_.fraction + s_.size, next_nominal});
}

void IncrementController::converged(int corrections) {
  const double end = target();
  if (plain_retry_) s_.extrapolation_failed = true;
  plain_retry_ = false;
  cutbacks_ = 0;
  s_.last_size = end - s_.fraction;
  s_.fraction = end;
  ++s_.converged_increments;
  // Regrow after an easy increment, but not straight back to a size that just failed (each retry that fails costs
  // a whole failed increment): that cap doubles after kEasyIncrementsBeforeRegrowth easy increments at it, never
  // beyond the nominal size. Easy: converged within a quarter of the allowed Newton corrections (elastoplastic
  // strands converge linearly in about 6 corrections at any size, so larger increments cost no more).
  const bool easy = corrections <= std::max(2, limits_.max_iterations / 4);
  s_.easy_at_cap = easy && s_.size >= s_.largest_size ? s_.easy_at_cap + 1 : 0;
  if (s_.easy_at_cap >= kEasyIncrementsBeforeRegrowth && s_.largest_size < nominal_) {
    s_.largest_size = std::min(nominal_, 2.0 * s_.largest_size);
    s_.easy_at_cap = 0;
  }
  if (easy) s_.size = std::min(s_.largest_size, 2.0 * s_.size);
}

Recovery IncrementController::failed(bool extrapolated) {
  plain_retry_ = false;
  // An extrapolated predictor can lead Newton astray where the plain one converges at the same size (past a yield
  // knee the last increment's motion is a poor guide): retry once without it before cutting.
  if (extrapolated) {
    plain_retry_ = true;
    return Recovery::kPlainRetry;
  }
  // Also give up when the size would fall below what max_cutbacks halvings of the nominal size allow: converging
  // and failing in turn could otherwise shrink the increments without bound (the load stalls at a limit).
  const double smallest = nominal_ * std::ldexp(1.0, -limits_.max_cutbacks);
  if (++cutbacks_ > limits_.max_cutbacks || 0.5 * s_.size < smallest * (1.0 - 1e-9)) {
    if (!limits_.automatic_stabilization || s_.stabilized) return Recovery::kStop;
    // The full sequence of cut-backs again, with the stabilization on, from a quarter of the nominal increment.
    s_.stabilized = true;
    cutbacks_ = 0;
    s_.size = s_.largest_size = kStabilizedRestartSize * nominal_;
    s_.easy_at_cap = 0;
    return Recovery::kStabilize;
  }
  s_.largest_size = std::min(s_.largest_size, 0.5 * s_.size);
  s_.easy_at_cap = 0;
  s_.size *= 0.5;
  return Recovery::kHalve;
}

}  // namespace strandfem
