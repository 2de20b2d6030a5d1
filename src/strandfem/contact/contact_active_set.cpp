// ContactSet's Newton support: the active set of closed points and the held stick/slip states of an
// increment (docs/theory.md, "Newton with contact").
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "strandfem/contact/contact_set.hpp"

namespace strandfem {

namespace {
constexpr double kSlidingDirectionTolerance = 1.0 - 1e-10;  // cosine between held and trial slip directions
constexpr double kReleaseTolerance = 1e-3;           // relative tension / cone excess tolerated at convergence
constexpr int kMaxFrictionSwitches = 6;
constexpr double kMaxAugmentationRatio = 0.9;  // an augmentation round extrapolates at most tenfold
// Releases + re-closings per point and increment; then an active point stays active (a point that keeps
// opening and closing carries next to no force, and holding it closed stops the chatter).
constexpr int kMaxNormalSwitches = 4;              // held friction switches per point and increment
// The augmented stick leaves line contacts carrying less than this share of the largest line load on the penalty
// stick: on cones that small a rigid stick turns thousands of lateral points between stick and slip at every round
// (docs/theory.md, "Augmented stick").
constexpr double kAugmentedLineLoadFraction = 0.1;
}  // namespace

std::array<double, 2> ContactSet::largest_normal_forces() const {
  std::array<double, 2> largest{0, 0};  // point, line
  for (std::size_t i = 0; i < points_.size(); ++i) {
    double& l = largest[points_[i].kind == ContactKind::kLine];
    l = std::max(l, std::abs(responses_[i].normal_force));
  }
  return largest;
}

void ContactSet::begin_increment(bool loading_continues) {
  augmentation_rounds_ = 0;
  for (ContactPoint& p : points_) {
    p.stick_offset = p.history.stick_offset;
    p.last_augmented_slip.setZero();
    p.active = p.history.closed;
    p.normal_switches = 0;
    p.friction_switches = 0;
    // Loading that goes on in the same sense keeps the slipping points slipping: start from there. Where it turns
    // (V back after V out) they stick again; held in their old slip, a reversal's first increment fails and is cut
    // back (docs/theory.md, "Newton with contact").
    p.friction_mode = loading_continues && p.history.closed && p.history.slipping ? FrictionMode::kHeldSlip : FrictionMode::kFree;
    const Vec3 d = -p.history.slip_direction;  // friction opposes the slip
    p.slip_direction = {d.x(), d.y(), d.z()};
  }
}

void ContactSet::activate_closed() {
  for (std::size_t i = 0; i < points_.size(); ++i) {
    ContactPoint& p = points_[i];
    const ContactResponse& r = responses_[i];
    if (r.status == ContactStatus::kOpen) continue;
    if (!p.active) {
      if (p.normal_switches > 0) ++p.normal_switches;  // closed again after a release
      p.active = true;
    }
    if (p.friction_mode != FrictionMode::kFree || !p.history.anchored || !(p.mu1 > 0) || !(r.normal_force > 0) ||
        p.friction_switches >= kMaxFrictionSwitches)
      continue;
    if (r.status == ContactStatus::kSlip && r.friction.norm() > 0) {
      p.friction_mode = FrictionMode::kHeldSlip;
      const Vec3 d = r.friction.normalized();
      p.slip_direction = {d.x(), d.y(), d.z()};
    } else {
      p.friction_mode = FrictionMode::kHeldStick;
    }
  }
}

int ContactSet::release_tensile() {
  // Tolerances relative to the largest contact force of each kind: a tension of 1e-12 N/mm is zero, and
  // releasing it only makes the point chatter about g = 0.
  const std::array<double, 2> largest = largest_normal_forces();
  int changed = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    ContactPoint& p = points_[i];
    const ContactResponse& r = responses_[i];
    if (r.status == ContactStatus::kOpen) continue;
    if (p.active && r.normal_force < -kReleaseTolerance * largest[p.kind == ContactKind::kLine] &&
        p.normal_switches < kMaxNormalSwitches) {
      p.active = false;
      ++p.normal_switches;
      ++changed;
      continue;
    }
    // Free points follow the plain law; points out of switches keep their held state (see below).
    if (p.friction_mode == FrictionMode::kFree || !(r.normal_force > 0) || p.friction_switches >= kMaxFrictionSwitches)
      continue;
    // Held friction states that the converged trial force contradicts are switched.
    const Vec3 trial = r.trial_friction.normalized();
    const Vec3 held(p.slip_direction[0], p.slip_direction[1], p.slip_direction[2]);
    auto hold_slip = [&] {
      p.friction_mode = FrictionMode::kHeldSlip;
      p.slip_direction = {trial.x(), trial.y(), trial.z()};
    };
    bool switched = false;
    if (p.friction_mode == FrictionMode::kHeldStick && r.slip_ratio < 1.0 - kReleaseTolerance) {
      hold_slip();
      switched = true;
    } else if (p.friction_mode == FrictionMode::kHeldSlip &&
               (r.slip_ratio > 1.0 + kReleaseTolerance || trial.dot(held) < 0.0)) {
      p.friction_mode = FrictionMode::kHeldStick;  // inside the cone, or the slip would reverse
      switched = true;
    } else if (p.friction_mode == FrictionMode::kHeldSlip && trial.dot(held) < kSlidingDirectionTolerance) {
      hold_slip();  // the slip direction turned (point contacts): hold the trial's direction
      switched = true;
    }
    if (!switched) continue;
    ++changed;
    // A point that has switched kMaxFrictionSwitches times keeps its held state for the rest of the
    // increment: the plain law would bring back the cycling, and the remaining mismatch is the last
    // switch's (counted in held_mismatches()).
    ++p.friction_switches;
  }
  return changed;
}

int ContactSet::augment_stick() {
  if (augmentation_rounds_ >= settings_.stick_augmentations) return 0;
  struct Update {
    std::size_t point;
    Vec3 elastic_slip;  // on the contact plane
    bool above_tolerance;
  };
  std::vector<Update> updates;
  bool any_above_tolerance = false;
  const double largest_line_load = largest_normal_forces()[1];
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& p = points_[i];
    const ContactResponse& r = responses_[i];
    if (!frictional(p) || r.status != ContactStatus::kStick || !(p.allowed_slip > 0) || !(r.normal_force > 0) ||
        (p.kind == ContactKind::kLine && !(r.normal_force > kAugmentedLineLoadFraction * largest_line_load)))
      continue;
    const Vec3 elastic_slip = r.tangential_gap + (p.stick_offset - r.normal.dot(p.stick_offset) * r.normal);
    const bool above = elastic_slip.norm() > settings_.stick_tolerance * p.allowed_slip;
    any_above_tolerance = any_above_tolerance || above;
    updates.push_back({i, elastic_slip, above});
  }
  if (!any_above_tolerance) return 0;
  converged_round_ = points_;  // what return_to_converged_round() goes back to
  // Every sticking point is updated (Uzawa), not only those above the tolerance: a point left with its slip below
  // the tolerance would keep it as play, different on loading and unloading, and the stick would dissipate.
  for (const auto& [i, elastic_slip, above] : updates) {
    ContactPoint& p = points_[i];
    const Vec3& n = responses_[i].normal;
    const Vec3 offset = p.stick_offset - n.dot(p.stick_offset) * n;
    // Points the stick holds against a stiff surrounding lose a fixed share of their slip per round: Aitken's
    // extrapolation of that geometric series; the offset stays within the cone (|offset| <= allowed slip).
    const double last = p.last_augmented_slip.norm();
    const double ratio = above && last > 0 && elastic_slip.dot(p.last_augmented_slip) > 0
                             ? std::min(elastic_slip.norm() / last, kMaxAugmentationRatio) : 0.0;
    Vec3 next = offset - elastic_slip / (1.0 - ratio);
    if (next.norm() > p.allowed_slip) next *= p.allowed_slip / next.norm();
    p.stick_offset = next;
    p.last_augmented_slip = elastic_slip;
  }
  ++augmentation_rounds_;
  return static_cast<int>(updates.size());
}

}  // namespace strandfem
