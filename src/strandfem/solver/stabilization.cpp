#include "strandfem/solver/stabilization.hpp"

#include <cmath>

namespace strandfem {

Mat3 inverse_left_jacobian(const Vec3& phi) {
  const double t = phi.norm();
  const Mat3 S = skew(phi);
  // 1/t² − (1 + cos t) / (2 t sin t), by its series below 1e-4 rad (the closed form cancels there).
  const double b = t < 1e-4 ? 1.0 / 12.0 + t * t / 720.0 : 1.0 / (t * t) - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  return Mat3::Identity() - 0.5 * S + b * S * S;
}

void ViscousStabilization::initialize(const std::vector<BeamElement>& elements, const std::vector<NodeState>& reference) {
  reference_stiffness_.resize(elements.size());
  for (std::size_t k = 0; k < elements.size(); ++k) {
    BeamElementState initial = elements[k].initial_state();  // a scratch state: the analysis's is not touched
    std::array<NodeState, 3> nodes;
    for (int i = 0; i < 3; ++i) nodes[i] = reference[elements[k].nodes()[i]];
    BeamElement::Output out;
    elements[k].evaluate(nodes, initial, true, out);
    reference_stiffness_[k] = out.tangent;
  }
}

namespace {
// The element's nodal motion since the converged state: per node the displacement, then the rotation vector.
ElementVector motion(const std::array<NodeState, 3>& now, const std::array<NodeState, 3>& converged) {
  ElementVector q;
  for (int i = 0; i < 3; ++i) {
    q.segment<3>(6 * i) = now[i].position - converged[i].position;
    q.segment<3>(6 * i + 3) = rotation_vector_from_quaternion(now[i].rotation * converged[i].rotation.conjugate());
  }
  return q;
}
}  // namespace

void ViscousStabilization::add(int element, const std::array<NodeState, 3>& now, const std::array<NodeState, 3>& converged,
                               double factor, ElementVector& residual, ElementMatrix* tangent) const {
  const ElementMatrix& K0 = reference_stiffness_[element];
  const ElementVector q = motion(now, converged);
  residual += factor * K0 * q;
  if (!tangent) return;
  // dq/d(du, dθ): identity for displacements, J_l⁻¹(φ) for a spin applied on the left.
  for (int i = 0; i < 3; ++i) {
    tangent->middleCols<3>(6 * i) += factor * K0.middleCols<3>(6 * i);
    tangent->middleCols<3>(6 * i + 3) += factor * K0.middleCols<3>(6 * i + 3) * inverse_left_jacobian(q.segment<3>(6 * i + 3));
  }
}

double ViscousStabilization::dissipated_energy(const std::vector<BeamElement>& elements, const std::vector<NodeState>& state,
                                               const std::vector<NodeState>& converged, double factor) const {
  if (factor == 0 || !initialized()) return 0.0;
  double energy = 0;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    std::array<NodeState, 3> now, before;
    for (int i = 0; i < 3; ++i) now[i] = state[elements[k].nodes()[i]], before[i] = converged[elements[k].nodes()[i]];
    const ElementVector q = motion(now, before);
    energy += factor * q.dot(reference_stiffness_[k] * q);
  }
  return energy;
}

}  // namespace strandfem
