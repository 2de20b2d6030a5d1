// Requirement: the beam element's residual is the gradient of its strain energy, its tangent is the
// exact derivative of the residual, and its strains are objective (zero under rigid motion).
#include "strandfem/beam/beam_element.hpp"

#include <gtest/gtest.h>

#include "test_helpers.hpp"

namespace strandfem {
namespace {

class BeamElementTest : public ::testing::Test {
 protected:
  BeamElementTest()
      : section_(SectionGeometry::circle(3.0, 0.3), Material{200000, 0.3, 7.85e-9}),
        reference_(testing::helical_reference()),
        element_({0, 1, 2}, &section_, reference_),
        state_(element_.initial_state()) {}
  ElasticSection section_;
  std::array<NodeState, 3> reference_;
  BeamElement element_;
  BeamElementState state_;
};

TEST_F(BeamElementTest, ReferenceConfigurationIsStressFree) {
  BeamElement::Output out;
  element_.evaluate(reference_, state_, true, out);
  EXPECT_LT(out.residual.norm(), 1e-8);
  EXPECT_NEAR(out.energy, 0.0, 1e-12);
}

TEST_F(BeamElementTest, ResidualIsFiniteDifferenceOfEnergy) {
  const auto state = testing::deformed_state(reference_);
  BeamElement::Output out;
  element_.evaluate(state, state_, false, out);
  const double h = 1e-6;
  for (int k = 0; k < 18; ++k) {
    Eigen::Matrix<double, 18, 1> d = Eigen::Matrix<double, 18, 1>::Zero();
    d[k] = h;
    BeamElement::Output plus, minus;
    element_.evaluate(testing::perturbed(state, d), state_, false, plus);
    element_.evaluate(testing::perturbed(state, -d), state_, false, minus);
    const double fd = (plus.energy - minus.energy) / (2 * h);
    EXPECT_NEAR(out.residual[k], fd, 1e-6 * out.residual.norm()) << "component " << k;
  }
}

TEST_F(BeamElementTest, TangentIsFiniteDifferenceOfResidual) {
  const auto state = testing::deformed_state(reference_);
  BeamElement::Output out;
  element_.evaluate(state, state_, true, out);
  ElementMatrix fd;
  const double h = 1e-7;
  for (int k = 0; k < 18; ++k) {
    Eigen::Matrix<double, 18, 1> d = Eigen::Matrix<double, 18, 1>::Zero();
    d[k] = h;
    BeamElement::Output plus, minus;
    element_.evaluate(testing::perturbed(state, d), state_, false, plus);
    element_.evaluate(testing::perturbed(state, -d), state_, false, minus);
    fd.col(k) = (plus.residual - minus.residual) / (2 * h);
  }
  EXPECT_LT((fd - out.tangent).norm() / out.tangent.norm(), 1e-6);
  // The residual from the second-derivative pass equals the first-derivative one.
  BeamElement::Output first;
  element_.evaluate(state, state_, false, first);
  EXPECT_LT((first.residual - out.residual).norm(), 1e-10 * out.residual.norm());
}

TEST_F(BeamElementTest, RigidMotionOfCurvedElementGivesZeroStrain) {
  // A rotation of 150 degrees about a skew axis plus a translation: no strain, no force.
  const Quaternion rigid(Eigen::AngleAxisd(150.0 * M_PI / 180.0, Vec3(1, -2, 0.5).normalized()));
  const Vec3 shift(3, -7, 11);
  auto moved = reference_;
  for (auto& n : moved) {
    n.position = rigid * n.position + shift;
    n.rotation = rigid * n.rotation;
  }
  BeamElement::Output out;
  element_.evaluate(moved, state_, true, out);
  for (const auto& p : state_.points) EXPECT_LT(p.strain.norm(), 1e-12);
  EXPECT_LT(out.residual.norm(), 1e-7);
  // The same deformation seen after a rigid motion gives the same energy (objectivity).
  const auto state = testing::deformed_state(reference_);
  auto moved_state = state;
  for (auto& n : moved_state) {
    n.position = rigid * n.position + shift;
    n.rotation = rigid * n.rotation;
  }
  BeamElement::Output a, b;
  element_.evaluate(state, state_, false, a);
  element_.evaluate(moved_state, state_, false, b);
  EXPECT_NEAR(a.energy, b.energy, 1e-10 * a.energy);
}

TEST_F(BeamElementTest, ConstantCurvatureIsRepresentedExactly) {
  // A straight element bent into an arc of curvature 1/R by nodal rotations about e3: K3 = 1/R exactly.
  std::array<NodeState, 3> straight;
  for (int i = 0; i < 3; ++i) straight[i].position = Vec3(5.0 * i, 0, 0);
  BeamElement element({0, 1, 2}, &section_, straight);
  const double R = 40.0;
  std::array<NodeState, 3> arc;
  for (int i = 0; i < 3; ++i) {
    const double phi = 5.0 * i / R;
    arc[i].position = Vec3(R * std::sin(phi), R * (1 - std::cos(phi)), 0);
    arc[i].rotation = Quaternion(Eigen::AngleAxisd(phi, Vec3::UnitZ()));
  }
  BeamElement::Output out;
  BeamElementState arc_state = element.initial_state();
  element.evaluate(arc, arc_state, false, out);
  for (const auto& p : arc_state.points) {
    EXPECT_NEAR(p.strain[5], 1.0 / R, 1e-12);
    EXPECT_NEAR(p.strain[3], 0.0, 1e-12);
    EXPECT_NEAR(p.strain[4], 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace strandfem
