// Coulomb friction at a contact point: the penalty-regularized return mapping on an elliptic (orthotropic)
// cone and the held stick/slip states used within an increment; templated for exact linearization.
#pragma once
#include <algorithm>
#include <cmath>

#include "strandfem/core/dual.hpp"
#include "strandfem/core/rotation.hpp"
#include "strandfem/core/types.hpp"

namespace strandfem {

enum class ContactStatus { kOpen = 0, kStick = 1, kSlip = 2 };
enum class FrictionMode { kFree, kHeldStick, kHeldSlip };  // see ContactPoint::friction_mode

// Parameters and working state of the friction law at one contact point.
struct FrictionLaw {
  double mu1 = 0, mu2 = 0;          // along direction 1 (the reference direction projected on the contact plane), and across
  double tangential_stiffness = 0;  // k_t: N/mm (point) or N/mm^2 (line), when allowed_slip is 0
  // > 0: the elastic-slip law, k_t = mu_i P / allowed_slip along direction i with the current P: a point sticks
  // while its elastic slip |g_T| stays below allowed_slip, whatever the pressure and the direction.
  double allowed_slip = 0;
  FrictionMode mode = FrictionMode::kFree;
  V3<double> slip_direction{0.0, 0.0, 0.0};  // held slip: unit direction of the friction force
};

// Held slip under the elastic-slip law: the force lies along the trial force plus this multiple of the held
// direction on the cone. The held direction alone has no stiffness across the slip, so an outer wire whose
// crossings all slide could swing sideways freely within a Newton correction (S32 under bending); the trial
// alone (the plain return) turns over when the trial passes near zero. Under eq. 2.6 (allowed_slip = 0) the
// trial is orders of magnitude beyond the cone and its direction is round-off: the held direction alone.
constexpr double kHeldSlipBlend = 0.5;

template <class T>
struct FrictionForce {
  V3<T> force{};        // friction force on the slave (per length for line contacts)
  V3<T> trial{};        // elastic trial -k_t g_T
  T q1{}, q2{};         // force components along directions 1 and 2
  double slip_ratio = 1e300;  // P / ||trial||_mu (> 1: the trial lies inside the cone)
  bool slipping = false;
};

// Friction for unit normal n, tangential gap g_T (on the contact plane) and normal force P. Direction 1 is
// `reference` (the strand axis, or a wire's tangent, which then moves with the wires) projected on the contact
// plane, direction 2 = direction 1 x n; the cone is (Q1/mu1)^2 + (Q2/mu2)^2 <= P^2.
template <class T>
FrictionForce<T> friction_force(const FrictionLaw& law, const V3<T>& n, const V3<T>& tangential_gap, const T& P,
                                const V3<T>& reference) {
  FrictionForce<T> f;
  V3<T> d1 = sub(reference, scale(dot(n, reference), n));
  d1 = scale(1.0 / sqrt(dot(d1, d1)), d1);
  const V3<T> d2 = cross(d1, n);
  if (law.allowed_slip > 0) {
    // k_i = mu_i P / allowed_slip in each direction: the cone is reached at the same elastic slip whatever the
    // direction, and mu2/mu1 changes the friction across without stiffening the stick along the axis.
    const T per_slip = P / law.allowed_slip;
    f.trial = add(scale(-law.mu1 * per_slip * dot(tangential_gap, d1), d1), scale(-law.mu2 * per_slip * dot(tangential_gap, d2), d2));
  } else {
    f.trial = scale(-T(law.tangential_stiffness), tangential_gap);
  }
  auto measure2 = [&](const T& c1, const T& c2) { return (c1 / law.mu1) * (c1 / law.mu1) + (c2 / law.mu2) * (c2 / law.mu2); };
  const T trial1 = dot(f.trial, d1), trial2 = dot(f.trial, d2);
  const T trial_measure2 = measure2(trial1, trial2);
  const double pressure = value_of(P);
  if (value_of(trial_measure2) > 0.0) f.slip_ratio = pressure / std::sqrt(value_of(trial_measure2));
  // Held slip: the force keeps a direction w on the current contact plane, Q = P w / |w|_mu. Under eq. 2.6, w is
  // the direction the slip started with, d (projected on the plane); under the elastic-slip law it turns with
  // the trial force (kHeldSlipBlend). Smooth, unlike P Q_tr / |Q_tr|_mu, whose direction turns over when Q_tr
  // passes near zero and sets Newton cycling; ContactSet checks it at convergence.
  const V3<T> held{T(law.slip_direction[0]), T(law.slip_direction[1]), T(law.slip_direction[2])};
  const V3<T> held_in_plane = sub(held, scale(dot(n, held), n));
  const T held_measure2 = measure2(dot(held_in_plane, d1), dot(held_in_plane, d2));
  T factor(0.0);  // Q = factor * (trial or held direction)
  if (law.mode == FrictionMode::kHeldSlip && value_of(held_measure2) > 1e-12) {
    const V3<T> w = law.allowed_slip > 0 ? add(f.trial, scale(kHeldSlipBlend * P / sqrt(held_measure2), held_in_plane))
                                         : held_in_plane;
    const T w1 = dot(w, d1), w2 = dot(w, d2);
    const T w_measure2 = measure2(w1, w2);
    if (value_of(w_measure2) > 1e-12 * value_of(held_measure2)) {  // w vanishes only where the slip reverses
      factor = P / sqrt(w_measure2);
      f.force = scale(factor, w);
      f.q1 = factor * w1;
      f.q2 = factor * w2;
      f.slipping = true;
      return f;
    }
  }
  if (law.mode != FrictionMode::kHeldStick && pressure <= 0.0) {
    // An active point in tension (only during Newton iterations) carries no friction.
    f.force = {T(0.0), T(0.0), T(0.0)};
    return f;
  }
  if (law.mode != FrictionMode::kHeldStick && value_of(trial_measure2) > pressure * pressure) {
    // Slip: radial return onto the ellipse, keeping the trial direction.
    factor = P / sqrt(trial_measure2);
    f.slipping = true;
  } else {
    factor = T(1.0);  // stick (or held stick): the elastic trial force
  }
  f.force = scale(factor, f.trial);
  f.q1 = factor * trial1;
  f.q2 = factor * trial2;
  return f;
}

}  // namespace strandfem
