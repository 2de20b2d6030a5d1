// Shared fixtures for unit tests: a curved, twisted 3-node element and multiplicative perturbations.
#pragma once
#include <array>
#include <cmath>

#include "strandfem/beam/beam_element.hpp"
#include "strandfem/geometry/strand.hpp"

namespace strandfem::testing {

// Three nodes on a helix (radius 4 mm, lay angle 15 deg), frames from the strand generator.
inline std::array<NodeState, 3> helical_reference() {
  StrandSpec strand;
  strand.length = 30;
  strand.materials["steel"] = {200000, 0.3, 7.85e-9};
  strand.layers = {{1, 3.0, "steel", 0, 1, 0}, {6, 3.0, "steel", 15.0 * M_PI / 180, 1, 0.3}};
  std::array<NodeState, 3> nodes;
  for (int i = 0; i < 3; ++i) {
    const auto p = wire_centerline(strand, 1, 0, 5.0 * i);
    nodes[i].position = p.position;
    nodes[i].rotation = Quaternion(p.frame).normalized();
  }
  return nodes;
}

// Applies the perturbation d (du, dtheta per node) multiplicatively: x + du, exp(dtheta^) Lambda.
inline std::array<NodeState, 3> perturbed(std::array<NodeState, 3> s, const Eigen::Matrix<double, 18, 1>& d) {
  for (int i = 0; i < 3; ++i) {
    s[i].position += d.segment<3>(6 * i);
    s[i].rotation = (quaternion_from_rotation_vector(d.segment<3>(6 * i + 3)) * s[i].rotation).normalized();
  }
  return s;
}

// A deformed state well away from the reference: stretch, bend and twist of order 1e-2.
inline std::array<NodeState, 3> deformed_state(const std::array<NodeState, 3>& reference) {
  Eigen::Matrix<double, 18, 1> d;
  d << 0.02, -0.01, 0.03, 0.05, -0.02, 0.04, -0.01, 0.02, 0.015, -0.03, 0.06, 0.02, 0.03, 0.01, -0.02, 0.01, -0.04,
      0.07;
  return perturbed(reference, d);
}

}  // namespace strandfem::testing
