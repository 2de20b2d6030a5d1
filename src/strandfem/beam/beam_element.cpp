#include "strandfem/beam/beam_element.hpp"

#include <cmath>
#include <stdexcept>

#include "strandfem/core/rotation.hpp"

namespace strandfem {
namespace {

using D1 = Dual<double, 18>;
using D2 = Dual<D1, 18>;

// Generalized strains (not yet reduced by the reference strains) at both integration points.
template <class T>
std::array<std::array<T, 6>, 2> integration_point_strains(const std::array<V3<T>, 3>& x,
                                                          const std::array<Quat<T>, 3>& q,
                                                          const std::array<BeamIntegrationPoint, 2>& points) {
  const Quat<T> reference_inverse = conjugate(q[1]);
  const V3<T> psi0 = rotation_vector_from_quat(multiply(reference_inverse, q[0]));
  const V3<T> psi2 = rotation_vector_from_quat(multiply(reference_inverse, q[2]));
  std::array<std::array<T, 6>, 2> strains;
  for (int g = 0; g < 2; ++g) {
    const auto& p = points[g];
    const V3<T> psi = add(scale(p.shape[0], psi0), scale(p.shape[2], psi2));
    const V3<T> dpsi = add(scale(p.shape_derivative[0], psi0), scale(p.shape_derivative[2], psi2));
    V3<T> dx = scale(p.shape_derivative[0], x[0]);
    dx = add(dx, scale(p.shape_derivative[1], x[1]));
    dx = add(dx, scale(p.shape_derivative[2], x[2]));
    const auto R = rotation_matrix(multiply(q[1], quat_from_rotation_vector(psi)));
    const V3<T> gamma = transpose_times(R, dx);
    const V3<T> kappa = right_jacobian_times(psi, dpsi);
    strains[g] = {gamma[0], gamma[1], gamma[2], kappa[0], kappa[1], kappa[2]};
  }
  return strains;
}

template <class T>
Quat<T> lift_quat(const Quaternion& q) {
  return {T(q.w()), T(q.x()), T(q.y()), T(q.z())};
}

}  // namespace

BeamElement::BeamElement(const std::array<int, 3>& nodes, const Section* section,
                         const std::array<NodeState, 3>& reference)
    : nodes_(nodes), section_(section) {
  const double xi_g = 1.0 / std::sqrt(3.0);
  std::array<V3<double>, 3> x;
  std::array<Quat<double>, 3> q;
  for (int i = 0; i < 3; ++i) {
    x[i] = {reference[i].position.x(), reference[i].position.y(), reference[i].position.z()};
    q[i] = lift_quat<double>(reference[i].rotation);
  }
  for (int g = 0; g < 2; ++g) {
    const double xi = g == 0 ? -xi_g : xi_g;
    auto& p = points_[g];
    p.shape = {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
    const std::array<double, 3> dN_dxi = {xi - 0.5, -2.0 * xi, xi + 0.5};
    Vec3 dX_dxi = Vec3::Zero();
    for (int i = 0; i < 3; ++i) dX_dxi += dN_dxi[i] * reference[i].position;
    const double jacobian = dX_dxi.norm();
    if (!(jacobian > 1e-12)) throw std::invalid_argument("beam element with zero length");
    for (int i = 0; i < 3; ++i) p.shape_derivative[i] = dN_dxi[i] / jacobian;
    p.weight_length = jacobian;  // Gauss weight 1
    p.committed = p.trial = section->initial_history();
  }
  const auto strains = integration_point_strains(x, q, points_);
  for (int g = 0; g < 2; ++g)
    for (int c = 0; c < 6; ++c) points_[g].reference_strain[c] = strains[g][c];
}

void BeamElement::evaluate(const std::array<NodeState, 3>& current, bool with_tangent, Output& out) {
  out.residual.setZero();
  out.tangent.setZero();
  out.energy = 0;
  if (!with_tangent) {
    // First derivatives only: perturb by (du_i, dtheta_i) with x_i + du_i, exp(dtheta_i^) Lambda_i.
    std::array<V3<D1>, 3> x;
    std::array<Quat<D1>, 3> q;
    for (int i = 0; i < 3; ++i) {
      V3<D1> spin;
      for (int k = 0; k < 3; ++k) {
        x[i][k] = D1::variable(current[i].position[k], 6 * i + k);
        spin[k] = D1::variable(0.0, 6 * i + 3 + k);
      }
      q[i] = multiply(quat_from_rotation_vector(spin), lift_quat<D1>(current[i].rotation));
    }
    const auto strains = integration_point_strains(x, q, points_);
    for (int g = 0; g < 2; ++g) {
      auto& p = points_[g];
      Eigen::Matrix<double, 6, 18> B;
      for (int c = 0; c < 6; ++c) {
        p.strain[c] = strains[g][c].value - p.reference_strain[c];
        for (int k = 0; k < 18; ++k) B(c, k) = strains[g][c].grad[k];
      }
      const SectionResponse s = section_->evaluate(p.strain, p.committed, p.trial);
      p.resultants = s.resultants;
      out.residual += p.weight_length * B.transpose() * s.resultants;
      out.energy += 0.5 * p.weight_length * p.strain.dot(s.resultants);
    }
    return;
  }
  // Mixed second derivatives: inner directions = virtual spins (eps), outer = increments (Delta), with
  // Lambda = exp(eps^) exp(Delta^) Lambda_current. The order matters: it makes d residual / d Delta the
  // consistent tangent of the multiplicative update (unsymmetric away from equilibrium).
  std::array<V3<D2>, 3> x;
  std::array<Quat<D2>, 3> q;
  for (int i = 0; i < 3; ++i) {
    V3<D2> virtual_spin, increment_spin;
    for (int k = 0; k < 3; ++k) {
      D2 position(D1::variable(current[i].position[k], 6 * i + k), 0);
      position.grad[6 * i + k] = D1(1.0);
      x[i][k] = position;
      virtual_spin[k] = D2(D1::variable(0.0, 6 * i + 3 + k), 0);
      increment_spin[k] = D2::variable(D1(0.0), 6 * i + 3 + k);
    }
    q[i] = multiply(quat_from_rotation_vector(virtual_spin),
                    multiply(quat_from_rotation_vector(increment_spin), lift_quat<D2>(current[i].rotation)));
  }
  const auto strains = integration_point_strains(x, q, points_);
  for (int g = 0; g < 2; ++g) {
    auto& p = points_[g];
    Eigen::Matrix<double, 6, 18> B;
    for (int c = 0; c < 6; ++c) {
      p.strain[c] = strains[g][c].value.value - p.reference_strain[c];
      for (int k = 0; k < 18; ++k) B(c, k) = strains[g][c].value.grad[k];
    }
    const SectionResponse s = section_->evaluate(p.strain, p.committed, p.trial);
    p.resultants = s.resultants;
    out.residual += p.weight_length * B.transpose() * s.resultants;
    out.energy += 0.5 * p.weight_length * p.strain.dot(s.resultants);
    out.tangent += p.weight_length * B.transpose() * s.tangent * B;
    for (int c = 0; c < 6; ++c) {
      const double stress = p.weight_length * s.resultants[c];
      for (int j = 0; j < 18; ++j)
        for (int i = 0; i < 18; ++i) out.tangent(i, j) += stress * strains[g][c].grad[j].grad[i];
    }
  }
}

void BeamElement::commit() {
  for (auto& p : points_) p.committed = p.trial;
}
void BeamElement::revert() {
  for (auto& p : points_) p.trial = p.committed;
}

}  // namespace strandfem
