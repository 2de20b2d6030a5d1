// The thick steel bar of cases/verification/tensioned_thick_beam.yaml and tensioned_core_bending.yaml, and its
// closed-form deflection: clamped at both ends, tension T, then V at midspan.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

#include "strandfem/post/bending.hpp"

namespace strandfem::verification {

struct ThickBar {
  double E = 200000, nu = 0.3, d = 20, L = 200, T = 157080, V = 2000;
  // The beam's law is per reference length (curvature and shear strain of the material): on the span stretched by
  // eps = T/(EA) it acts as EI (1 + eps) and S (1 + eps) on the current length.
  double stretch() const { return 1 + T / (E * area()); }
  double area() const { return std::numbers::pi * d * d / 4; }
  double inertia() const { return std::numbers::pi * std::pow(d, 4) / 64; }
  double shear_stiffness() const { return 6 * (1 + nu) / (7 + 6 * nu) * E / (2 * (1 + nu)) * area(); }
  // The Timoshenko form of eq. 3.2 at the node z0 (reference position), on the stretched span.
  double deflection(double z0) const {
    const double s = stretch(), x = std::min(z0, L - z0) * s;
    return tensioned_timoshenko_deflection(V, T, E * inertia() * s, shear_stiffness() * s, L * s, x);
  }
};

}  // namespace strandfem::verification
