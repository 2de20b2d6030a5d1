// ContactSet's Newton support: the active set of closed points and the held stick/slip states of an
// increment (docs/theory.md, "Newton with contact").
#include <algorithm>
#include <cmath>

#include "strandfem/contact/contact_set.hpp"

namespace strandfem {

namespace {
constexpr double kSlidingDirectionTolerance = 1.0 - 1e-10;  // cosine between held and trial slip directions
constexpr double kReleaseTolerance = 1e-3;           // relative tension / cone excess tolerated at convergence
constexpr int kMaxFrictionSwitches = 6;              // held friction switches per point and increment
}  // namespace

void ContactSet::begin_increment() {
  for (ContactPoint& p : points_) {
    p.active = p.history.closed;
    p.released = false;
    p.friction_switches = 0;
    // Loading that goes on in the same sense keeps the slipping points slipping: start from there.
    p.friction_mode = p.history.closed && p.history.slipping ? FrictionMode::kHeldSlip : FrictionMode::kFree;
    const Vec3& d = p.history.friction_direction;
    p.slip_direction = {d.x(), d.y(), d.z()};
  }
}

void ContactSet::activate_closed() {
  for (std::size_t i = 0; i < points_.size(); ++i) {
    ContactPoint& p = points_[i];
    const ContactResponse& r = responses_[i];
    if (r.status == ContactStatus::kOpen) continue;
    if (!p.released) p.active = true;
    if (p.friction_mode != FrictionMode::kFree || !p.history.closed || !(p.mu1 > 0) || !(r.normal_force > 0) ||
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
  double largest[2] = {0, 0};
  for (std::size_t i = 0; i < points_.size(); ++i) {
    double& l = largest[points_[i].kind == ContactKind::kLine];
    l = std::max(l, std::abs(responses_[i].normal_force));
  }
  int changed = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    ContactPoint& p = points_[i];
    const ContactResponse& r = responses_[i];
    if (r.status == ContactStatus::kOpen) continue;
    if (p.active && r.normal_force < -kReleaseTolerance * largest[p.kind == ContactKind::kLine]) {
      p.active = false;
      p.released = true;
      ++changed;
      continue;
    }
    if (p.friction_mode == FrictionMode::kFree || !(r.normal_force > 0)) continue;
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
      // The slip direction turned (point contacts): the plain return mapping, exact in direction, for the
      // rest of the increment (deep in slip it is smooth enough).
      p.friction_mode = FrictionMode::kFree;
      p.friction_switches = kMaxFrictionSwitches;
      ++changed;
      continue;
    }
    if (!switched) continue;
    ++changed;
    // A point that keeps switching goes back to the plain law.
    if (++p.friction_switches >= kMaxFrictionSwitches) p.friction_mode = FrictionMode::kFree;
  }
  return changed;
}

}  // namespace strandfem
