#include "strandfem/beam/beam_element.hpp"

#include <cmath>
#include <stdexcept>

#include "strandfem/core/archive.hpp"
#include "strandfem/core/rotation.hpp"

namespace strandfem {
namespace {

// Dual numbers over the 9 nodal spins only: positions enter the strains linearly (Gamma = R^T x'), so their
// derivatives are written out below, which makes the nested (second-order) numbers 3.6 times smaller
// than with all 18 nodal degrees of freedom as directions.
using D1 = Dual<double, 9>;
using D2 = Dual<D1, 9>;

// Section rotation R (rows of the matrix, R[row][col]) and curvature K at an integration point.
template <class T>
struct PointKinematics {
  std::array<V3<T>, 3> rotation;
  V3<T> curvature;
};

template <class T>
std::array<PointKinematics<T>, 2> point_kinematics(const std::array<Quat<T>, 3>& q,
                                                   const std::array<BeamIntegrationPoint, 2>& points) {
  const Quat<T> reference_inverse = conjugate(q[1]);
  const V3<T> psi0 = rotation_vector_from_quat(multiply(reference_inverse, q[0]));
  const V3<T> psi2 = rotation_vector_from_quat(multiply(reference_inverse, q[2]));
  std::array<PointKinematics<T>, 2> result;
  for (int g = 0; g < 2; ++g) {
    const auto& p = points[g];
    const V3<T> psi = add(scale(p.shape[0], psi0), scale(p.shape[2], psi2));
    const V3<T> dpsi = add(scale(p.shape_derivative[0], psi0), scale(p.shape_derivative[2], psi2));
    result[g].rotation = rotation_matrix(multiply(q[1], quat_from_rotation_vector(psi)));
    result[g].curvature = right_jacobian_times(psi, dpsi);
  }
  return result;
}

// Centreline tangent x' = sum N_i' x_i at an integration point.
Vec3 centreline_tangent(const std::array<NodeState, 3>& nodes, const BeamIntegrationPoint& p) {
  return p.shape_derivative[0] * nodes[0].position + p.shape_derivative[1] * nodes[1].position +
         p.shape_derivative[2] * nodes[2].position;
}

// Generalized strains [Gamma = R^T x', K] (not yet reduced by the reference strains).
template <class T>
std::array<T, 6> generalized_strains(const PointKinematics<T>& k, const Vec3& tangent) {
  std::array<T, 6> strain;
  for (int c = 0; c < 3; ++c) {
    strain[c] = k.rotation[0][c] * tangent[0] + k.rotation[1][c] * tangent[1] + k.rotation[2][c] * tangent[2];
    strain[3 + c] = k.curvature[c];
  }
  return strain;
}

template <class T>
Quat<T> lift_quat(const Quaternion& q) {
  return {T(q.w()), T(q.x()), T(q.y()), T(q.z())};
}

// exp(eps^) exp(Delta^) of node `node`'s virtual spin eps (the inner directions 3 node + k) and spin increment Delta
// (the outer ones), as far as the nested numbers carry it: first order in each and their product. There
// exp(eps^) = (1, eps/2) and exp(Delta^) = (1, Delta/2) exactly, as |eps|^2 and |Delta|^2 vanish, so the product
// is (1 - eps.Delta/4, (eps + Delta)/2 + eps x Delta/4), set here entry by entry.
Quat<D2> spin_perturbation(int node) {
  Quat<D2> p;
  std::array<D2*, 3> vector{&p.x, &p.y, &p.z};
  for (int k = 0; k < 3; ++k) {
    const int d = 3 * node + k;
    p.w.grad[d].grad[d] = -0.25;
    vector[k]->value.grad[d] = 0.5;
    vector[k]->grad[d].value = 0.5;
    // (eps x Delta)_k = eps_(k+1) Delta_(k+2) - eps_(k+2) Delta_(k+1): outer index first.
    const int next = 3 * node + (k + 1) % 3, after = 3 * node + (k + 2) % 3;
    vector[k]->grad[after].grad[next] = 0.25;
    vector[k]->grad[next].grad[after] = -0.25;
  }
  return p;
}

double plain_value(const D1& v) { return v.value; }
double plain_value(const D2& v) { return v.value.value; }

// Strain-displacement matrix B = d strain / d (du, dtheta) of the three nodes. Position columns are
// N_a' R[k][c] (Gamma rows only); spin columns are the first-order dual parts, read by spin_derivative.
template <class T, class SpinDerivative>
Eigen::Matrix<double, 6, 18> strain_operator(const PointKinematics<T>& k, const std::array<T, 6>& strain,
                                             const BeamIntegrationPoint& p, SpinDerivative spin_derivative) {
  Eigen::Matrix<double, 6, 18> B = Eigen::Matrix<double, 6, 18>::Zero();
  for (int a = 0; a < 3; ++a)
    for (int d = 0; d < 3; ++d)
      for (int c = 0; c < 3; ++c) B(c, 6 * a + d) = p.shape_derivative[a] * plain_value(k.rotation[d][c]);
  for (int c = 0; c < 6; ++c)
    for (int a = 0; a < 3; ++a)
      for (int d = 0; d < 3; ++d) B(c, 6 * a + 3 + d) = spin_derivative(strain[c], 3 * a + d);
  return B;
}

}  // namespace

BeamElement::BeamElement(const std::array<int, 3>& nodes, const Section* section,
                         const std::array<NodeState, 3>& reference)
    : nodes_(nodes), section_(section) {
  const double xi_g = 1.0 / std::sqrt(3.0);
  std::array<Quat<double>, 3> q;
  for (int i = 0; i < 3; ++i) q[i] = lift_quat<double>(reference[i].rotation);
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
  }
  const auto kinematics = point_kinematics(q, points_);
  for (int g = 0; g < 2; ++g) {
    const auto strain = generalized_strains(kinematics[g], centreline_tangent(reference, points_[g]));
    for (int c = 0; c < 6; ++c) points_[g].reference_strain[c] = strain[c];
  }
}

BeamElementState BeamElement::initial_state() const {
  BeamElementState state;
  for (SectionPointState& p : state.points) p.committed = p.trial = section_->initial_history();
  return state;
}

void BeamElement::evaluate(const std::array<NodeState, 3>& current, BeamElementState& state, bool with_tangent,
                           Output& out) const {
  out.residual.setZero();
  out.tangent.setZero();
  out.energy = 0;
  if (!with_tangent) {
    // First derivatives only: spin perturbations exp(dtheta_i^) Lambda_i.
    std::array<Quat<D1>, 3> q;
    for (int i = 0; i < 3; ++i) {
      V3<D1> spin;
      for (int k = 0; k < 3; ++k) spin[k] = D1::variable(0.0, 3 * i + k);
      q[i] = multiply(quat_from_rotation_vector(spin), lift_quat<D1>(current[i].rotation));
    }
    const auto kinematics = point_kinematics(q, points_);
    for (int g = 0; g < 2; ++g) {
      const BeamIntegrationPoint& p = points_[g];
      SectionPointState& ps = state.points[g];
      const auto strain = generalized_strains(kinematics[g], centreline_tangent(current, p));
      const auto B = strain_operator(kinematics[g], strain, p, [](const D1& e, int k) { return e.grad[k]; });
      for (int c = 0; c < 6; ++c) ps.strain[c] = strain[c].value - p.reference_strain[c];
      const SectionResponse s = section_->evaluate(ps.strain, ps.committed, ps.trial);
      ps.resultants = s.resultants;
      out.residual += p.weight_length * B.transpose() * s.resultants;
      out.energy += 0.5 * p.weight_length * ps.strain.dot(s.resultants);
    }
    return;
  }
  // Mixed second derivatives: inner directions = virtual spins (eps), outer = spin increments (Delta),
  // with Lambda = exp(eps^) exp(Delta^) Lambda_current. The order matters: it makes d residual / d Delta the
  // consistent tangent of the multiplicative update (unsymmetric away from equilibrium).
  std::array<Quat<D2>, 3> q;
  for (int i = 0; i < 3; ++i) q[i] = multiply(spin_perturbation(i), lift_quat<double>(current[i].rotation));
  const auto kinematics = point_kinematics(q, points_);
  for (int g = 0; g < 2; ++g) {
    const BeamIntegrationPoint& p = points_[g];
    SectionPointState& ps = state.points[g];
    const PointKinematics<D2>& k = kinematics[g];
    const auto strain = generalized_strains(k, centreline_tangent(current, p));
    const auto B = strain_operator(k, strain, p, [](const D2& e, int j) { return e.value.grad[j]; });
    for (int c = 0; c < 6; ++c) ps.strain[c] = strain[c].value.value - p.reference_strain[c];
    const SectionResponse s = section_->evaluate(ps.strain, ps.committed, ps.trial);
    ps.resultants = s.resultants;
    out.residual += p.weight_length * B.transpose() * s.resultants;
    out.energy += 0.5 * p.weight_length * ps.strain.dot(s.resultants);
    out.tangent += p.weight_length * B.transpose() * s.tangent * B;
    // Geometric part: stresses times the second derivatives of the strains. The strains' spin-spin
    // derivatives are the nested dual parts; position-spin ones come from R s_Gamma, as Gamma = R^T x'.
    std::array<double, 6> stress;
    for (int c = 0; c < 6; ++c) stress[c] = p.weight_length * s.resultants[c];
    V3<D2> rotated_shear;  // R [N, Q2, Q3]
    for (int d = 0; d < 3; ++d)
      rotated_shear[d] = stress[0] * k.rotation[d][0] + stress[1] * k.rotation[d][1] + stress[2] * k.rotation[d][2];
    for (int b = 0; b < 3; ++b)
      for (int m = 0; m < 3; ++m) {
        const int outer = 3 * b + m;
        for (int a = 0; a < 3; ++a)
          for (int d = 0; d < 3; ++d) {
            const int inner = 3 * a + d;
            double spin_spin = 0;
            for (int c = 0; c < 6; ++c) spin_spin += stress[c] * strain[c].grad[outer].grad[inner];
            out.tangent(6 * a + 3 + d, 6 * b + 3 + m) += spin_spin;
            out.tangent(6 * a + d, 6 * b + 3 + m) += p.shape_derivative[a] * rotated_shear[d].grad[outer].value;
            out.tangent(6 * a + 3 + d, 6 * b + m) += p.shape_derivative[b] * rotated_shear[m].value.grad[inner];
          }
      }
  }
}

void BeamElementState::commit() {
  for (auto& p : points) p.committed = p.trial;
}
void BeamElementState::revert() {
  for (auto& p : points) p.trial = p.committed;
}

void BeamElementState::save_history(ArchiveWriter& out) const {
  for (const auto& p : points) out.vector(p.committed);
}
void BeamElementState::restore_history(ArchiveReader& in) {
  for (auto& p : points) {
    SectionHistory h = in.vector<double>();
    if (h.size() != p.committed.size()) throw ArchiveError("checkpoint does not match this model: section history size differs");
    p.committed = p.trial = std::move(h);
  }
}

}  // namespace strandfem
