// Requirement: the viscous stabilization's force is factor · K₀ q (K₀: the element's elastic tangent at the
// reference, q: the motion since the converged state), it does not resist a rigid translation, its tangent is the
// exact derivative of its force, and the energy it reports is Σ factor qᵀ K₀ q.
#include "strandfem/solver/stabilization.hpp"

#include <gtest/gtest.h>

#include "test_helpers.hpp"

namespace strandfem {
namespace {

class StabilizationTest : public ::testing::Test {
 protected:
  StabilizationTest()
      : section_(SectionGeometry::circle(3.0, 0.3), Material{200000, 0.3, 7.85e-9}),
        reference_(testing::helical_reference()),
        elements_{BeamElement({0, 1, 2}, &section_, reference_)},
        nodes_(reference_.begin(), reference_.end()) {
    stabilization_.initialize(elements_, nodes_);
  }
  ElementVector force(const std::array<NodeState, 3>& now, const std::array<NodeState, 3>& converged,
                      ElementMatrix* tangent = nullptr) const {
    ElementVector r = ElementVector::Zero();
    if (tangent) tangent->setZero();
    stabilization_.add(0, now, converged, kFactor, r, tangent);
    return r;
  }
  static constexpr double kFactor = 0.01;
  ElasticSection section_;
  std::array<NodeState, 3> reference_;
  std::vector<BeamElement> elements_;
  std::vector<NodeState> nodes_;
  ViscousStabilization stabilization_;
};

TEST(InverseLeftJacobian, IsTheDerivativeOfTheLogarithm) {
  for (const Vec3& phi : {Vec3(0.3, -0.2, 0.5), Vec3(1e-6, 2e-6, -1e-6), Vec3(2.0, 0.5, -1.0)}) {
    const Mat3 analytic = inverse_left_jacobian(phi);
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      const Vec3 d = h * Vec3::Unit(j);
      const Quaternion base = quaternion_from_rotation_vector(phi);
      const Vec3 fd = (rotation_vector_from_quaternion(quaternion_from_rotation_vector(d) * base) -
                       rotation_vector_from_quaternion(quaternion_from_rotation_vector(-d) * base)) /
                      (2 * h);
      EXPECT_LT((fd - analytic.col(j)).norm(), 1e-7) << "phi " << phi.transpose() << " column " << j;
    }
  }
}

TEST_F(StabilizationTest, ForceIsElasticStiffnessTimesMotion) {
  Eigen::Matrix<double, 18, 1> d;
  d << 1e-3, -2e-3, 3e-3, 1e-4, -2e-4, 1e-4, 2e-3, 1e-3, -1e-3, 3e-4, 1e-4, -1e-4, -1e-3, 2e-3, 1e-3, -2e-4, 1e-4, 2e-4;
  const auto now = testing::perturbed(reference_, d);
  // K₀ is the element's own tangent at the reference: the force must match the linearised elastic force.
  BeamElementState initial = elements_[0].initial_state();
  BeamElement::Output at_reference;
  elements_[0].evaluate(reference_, initial, true, at_reference);
  const ElementVector expected = kFactor * at_reference.tangent * d;
  EXPECT_LT((force(now, reference_) - expected).norm(), 1e-3 * expected.norm());
}

TEST_F(StabilizationTest, RigidTranslationCostsNothing) {
  Eigen::Matrix<double, 18, 1> translation = Eigen::Matrix<double, 18, 1>::Zero();
  for (int i = 0; i < 3; ++i) translation.segment<3>(6 * i) = Vec3(0.2, -0.1, 0.5);
  Eigen::Matrix<double, 18, 1> stretch = Eigen::Matrix<double, 18, 1>::Zero();
  stretch[2 + 12] = 0.01;  // the same magnitude as an axial deformation, for scale
  const double scale = force(testing::perturbed(reference_, stretch), reference_).norm();
  EXPECT_LT(force(testing::perturbed(reference_, translation), reference_).norm(), 1e-8 * scale);
}

TEST_F(StabilizationTest, TangentIsFiniteDifferenceOfForce) {
  // Converged at a deformed state, now a further motion away, rotations of order 0.1 rad.
  const auto converged = testing::deformed_state(reference_);
  Eigen::Matrix<double, 18, 1> d;
  d << 0.01, 0.02, -0.01, 0.1, -0.05, 0.08, -0.02, 0.01, 0.03, -0.07, 0.12, 0.02, 0.02, -0.01, 0.01, 0.05, 0.09, -0.1;
  const auto now = testing::perturbed(converged, d);
  ElementMatrix tangent;
  force(now, converged, &tangent);
  const double h = 1e-6;
  ElementMatrix fd;
  for (int k = 0; k < 18; ++k) {
    Eigen::Matrix<double, 18, 1> e = Eigen::Matrix<double, 18, 1>::Zero();
    e[k] = h;
    fd.col(k) = (force(testing::perturbed(now, e), converged) - force(testing::perturbed(now, -e), converged)) / (2 * h);
  }
  EXPECT_LT((fd - tangent).norm(), 1e-6 * tangent.norm());
  // Without the rotation Jacobian the tangent would be off by far more than the tolerance above.
  BeamElementState initial = elements_[0].initial_state();
  BeamElement::Output at_reference;
  elements_[0].evaluate(reference_, initial, true, at_reference);
  const ElementMatrix plain = kFactor * at_reference.tangent;
  EXPECT_GT((fd - plain).norm(), 1e-3 * tangent.norm());
}

TEST_F(StabilizationTest, EnergyIsQuadraticFormOfTheMotion) {
  Eigen::Matrix<double, 18, 1> d;
  d << 1e-3, -2e-3, 3e-3, 1e-4, -2e-4, 1e-4, 2e-3, 1e-3, -1e-3, 3e-4, 1e-4, -1e-4, -1e-3, 2e-3, 1e-3, -2e-4, 1e-4, 2e-4;
  const auto now = testing::perturbed(reference_, d);
  const std::vector<NodeState> state(now.begin(), now.end());
  const ElementVector f = force(now, reference_);
  // The motion of a perturbation from the reference is d itself (rotation vectors of small spins): f · d.
  EXPECT_NEAR(stabilization_.dissipated_energy(elements_, state, nodes_, kFactor), f.dot(d), 1e-6 * std::abs(f.dot(d)));
  EXPECT_GT(f.dot(d), 0.0);
  EXPECT_EQ(stabilization_.dissipated_energy(elements_, state, nodes_, 0.0), 0.0);
}

}  // namespace
}  // namespace strandfem
