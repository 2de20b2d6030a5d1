// Requirement: the wire plasticity of issue 8. The fibre return mapping and its consistent tangent against
// finite differences, the uniaxial cycle against the closed-form bilinear kinematic loop (Bauschinger
// effect), the fibre section's elastic stiffness, plastic moment 4/3 sigma_y r^3 and residual curvature
// against closed forms, and the plastic state's commit/revert in the beam element.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "strandfem/beam/beam_element.hpp"
#include "strandfem/beam/fibre_section.hpp"
#include "test_helpers.hpp"

namespace strandfem {
namespace {

// The closed forms below are in engineering stress and strain.
Material steel(double tangent_modulus, StressMeasure measure = StressMeasure::engineering) {
  Material m{188000, 0.3, 0, "steel"};
  m.plasticity = BilinearHardening{1540, tangent_modulus, measure};
  return m;
}

// Stress of the closed-form bilinear kinematic loop along a piecewise monotone strain path (uniaxial):
// the elastic range [back - sigma_y, back + sigma_y] moves with back = H eps_p.
double bilinear_kinematic_stress(const std::vector<double>& path, double E, double Et, double yield) {
  const double H = E * Et / (E - Et);
  double plastic = 0, strain = 0;
  double stress = 0;
  for (double target : path) {
    // From `strain` to `target`: elastic until the moving limit, then slope Et.
    const double direction = target > strain ? 1.0 : -1.0;
    const double limit = H * plastic + direction * yield;  // stress at which it yields in this direction
    const double elastic_end = strain + (limit - stress) / E;
    if (direction * (target - elastic_end) <= 0) {
      stress += E * (target - strain);
    } else {
      stress = limit + Et * (target - elastic_end);
      plastic = target - stress / E;
    }
    strain = target;
  }
  return stress;
}

TEST(FibrePlasticity, UniaxialCycleIsTheClosedFormBilinearKinematicLoop) {
  const Material m = steel(24600);
  const double yield_strain = 1540.0 / 188000.0;
  std::vector<double> path;
  // Up to 3 eps_y, down to -2 eps_y, up to 4 eps_y, down to 0: in steps of 0.1 eps_y.
  for (double target : {3.0, -2.0, 4.0, 0.0}) {
    const double from = path.empty() ? 0.0 : path.back() / yield_strain;
    const int steps = static_cast<int>(std::lround(std::abs(target - from) / 0.1));
    for (int i = 1; i <= steps; ++i) path.push_back(yield_strain * (from + (target - from) * i / steps));
  }
  FibrePlasticState state;
  double max_error = 0;
  bool reversed_yield_seen = false;
  for (std::size_t i = 0; i < path.size(); ++i) {
    FibrePlasticState next;
    const FibreResponse r = j2_fibre_return(Vec3(path[i], 0, 0), m, state, next);
    state = next;
    const std::vector<double> so_far(path.begin(), path.begin() + static_cast<long>(i) + 1);
    const double expected = bilinear_kinematic_stress(so_far, 188000, 24600, 1540);
    max_error = std::max(max_error, std::abs(r.stress[0] - expected));
    EXPECT_NEAR(r.stress[1], 0.0, 1e-9);
    // Bauschinger: after the first loading, reverse yielding starts at sigma_max - 2 sigma_y, above -sigma_y.
    if (r.yielding && r.stress[0] < 0 && r.stress[0] > -1540.0) reversed_yield_seen = true;
  }
  EXPECT_LT(max_error, 1e-6 * 1540.0);
  EXPECT_TRUE(reversed_yield_seen);
}

// Central differences of a fibre law's stress (strain -> stress) at `strain`.
template <class Law>
Mat3 finite_difference_tangent(const Law& stress_of, const Vec3& strain) {
  Mat3 fd;
  const double h = 1e-9;
  for (int k = 0; k < 3; ++k) {
    const Vec3 d = h * Vec3::Unit(k);
    fd.col(k) = (stress_of(strain + d) - stress_of(strain - d)) / (2 * h);
  }
  return fd;
}

TEST(FibrePlasticity, ConsistentTangentIsTheFiniteDifferenceOfTheReturn) {
  const Material m = steel(5500);
  FibrePlasticState committed;
  committed.plastic_strain = Vec3(0.002, -0.001, 0.0005);
  committed.back_stress = Vec3(60, -10, 5);
  const std::vector<Vec3> strains = {Vec3(0.012, 0.001, -0.002), Vec3(-0.006, 0.008, 0.001), Vec3(0.003, -0.0005, 0.0002)};
  int plastic_cases = 0;
  for (const Vec3& strain : strains) {
    FibrePlasticState trial;
    const FibreResponse r = j2_fibre_return(strain, m, committed, trial);
    plastic_cases += r.yielding;
    const Mat3 fd = finite_difference_tangent(
        [&](const Vec3& e) { FibrePlasticState scratch; return j2_fibre_return(e, m, committed, scratch).stress; }, strain);
    EXPECT_LT((fd - r.tangent).norm(), 1e-6 * r.tangent.norm()) << "strain " << strain.transpose();
    // The returned stress lies on the moved yield surface.
    if (r.yielding) EXPECT_NEAR(von_mises(r.stress - trial.back_stress), 1540.0, 1e-8 * 1540.0);
  }
  EXPECT_GE(plastic_cases, 2);
}

// True-stress law: the bilinear law holds between true stress and logarithmic strain, and the section
// integrates true stress over the current area of an incompressible fibre, tau / (1 + eps) per reference area.
TEST(FibrePlasticity, TrueStressLawIsBilinearInLogarithmicStrainOverTheCurrentArea) {
  const Material m = steel(5500, StressMeasure::true_stress);
  FibrePlasticState state;
  double max_error = 0;
  for (int i = 1; i <= 70; ++i) {  // monotonic tension to eps = 0.07 (the 120-wire strand's last strain)
    const double strain = 0.001 * i;
    FibrePlasticState next;
    const FibreResponse r = fibre_response(Vec3(strain, 0, 0), m, state, next);
    state = next;
    const double log_strain = std::log1p(strain);
    const double true_stress = bilinear_kinematic_stress({log_strain}, 188000, 5500, 1540);
    max_error = std::max(max_error, std::abs(r.material_stress[0] - true_stress));
    EXPECT_NEAR(r.stress[0], true_stress / (1 + strain), 1e-9 * 1540.0) << "strain " << strain;
  }
  EXPECT_LT(max_error, 1e-6 * 1540.0);
  EXPECT_GT(state.equivalent_plastic_strain, 0.05);
  // At 7 % the section stress is 7.2 % under the engineering law with the same (sigma_y, Et).
  const FibrePlasticState virgin;
  FibrePlasticState scratch;
  const double engineering = fibre_response(Vec3(0.07, 0, 0), steel(5500), virgin, scratch).stress[0];
  const double true_measure = fibre_response(Vec3(0.07, 0, 0), m, virgin, scratch).stress[0];
  EXPECT_NEAR(true_measure / engineering, (1540 + 5500 * (std::log1p(0.07) - 1540 / 188000.0)) /
                                              (1540 + 5500 * (0.07 - 1540 / 188000.0)) / 1.07, 1e-9);
  // The wire section under uniform stretch carries that stress over its reference area.
  const FibreSection section(SectionGeometry::circle(3.73, m.poisson_ratio), m);
  SectionHistory committed = section.initial_history(), trial;
  const SectionResponse stretched = section.evaluate(Vec6(0.07, 0, 0, 0, 0, 0), committed, trial);
  EXPECT_NEAR(stretched.resultants[0], section.geometry().area * true_measure, 1e-9 * stretched.resultants[0]);
}

TEST(FibrePlasticity, TrueStressTangentIsTheFiniteDifferenceOfTheResponse) {
  const Material m = steel(5500, StressMeasure::true_stress);
  FibrePlasticState committed;
  committed.plastic_strain = Vec3(0.02, -0.001, 0.0005);
  committed.back_stress = Vec3(90, -10, 5);
  int plastic_cases = 0;
  for (const Vec3& strain : {Vec3(0.045, 0.001, -0.002), Vec3(0.01, 0.008, 0.001), Vec3(0.03, -0.0005, 0.0002)}) {
    FibrePlasticState trial;
    const FibreResponse r = fibre_response(strain, m, committed, trial);
    plastic_cases += r.yielding;
    const Mat3 fd = finite_difference_tangent(
        [&](const Vec3& e) { FibrePlasticState scratch; return fibre_response(e, m, committed, scratch).stress; }, strain);
    EXPECT_LT((fd - r.tangent).norm(), 1e-6 * r.tangent.norm()) << "strain " << strain.transpose();
  }
  EXPECT_GE(plastic_cases, 2);
}

TEST(FibreSection, ElasticStiffnessIsTheClosedFormSection) {
  const Material m = steel(24600);
  const SectionGeometry g = SectionGeometry::circle(3.73, m.poisson_ratio);
  const FibreSection fibres(g, m);
  const ElasticSection elastic(g, m);
  SectionHistory committed = fibres.initial_history(), trial;
  const Vec6 small = Vec6(1e-4, 2e-5, -1e-5, 3e-6, -2e-6, 1e-6);
  const SectionResponse r = fibres.evaluate(small, committed, trial);
  SectionHistory none;
  const SectionResponse e = elastic.evaluate(small, none, none);
  EXPECT_LT((r.tangent - e.tangent).norm(), 1e-9 * e.tangent.norm());
  EXPECT_LT((r.resultants - e.resultants).norm(), 1e-9 * e.resultants.norm());
}

TEST(FibreSection, PlasticMomentOfAWireWithinOnePercentInAnyDirection) {
  const double radius = 1.865;
  const Material m = steel(0.0);  // perfectly plastic: the moment saturates at the plastic moment
  const FibreSection section(SectionGeometry::circle(2 * radius, m.poisson_ratio), m);
  const double plastic_moment = 4.0 / 3.0 * 1540.0 * std::pow(radius, 3);
  const double yield_curvature = 1540.0 / (188000.0 * radius);
  for (double angle : {0.0, 10.0, 22.5, 37.0, 45.0, 90.0}) {
    const double a = angle * std::numbers::pi / 180.0;
    Vec6 strain = Vec6::Zero();
    strain[4] = 60 * yield_curvature * std::cos(a);
    strain[5] = 60 * yield_curvature * std::sin(a);
    SectionHistory committed = section.initial_history(), trial;
    const SectionResponse r = section.evaluate(strain, committed, trial);
    const double moment = std::hypot(r.resultants[4], r.resultants[5]);
    EXPECT_NEAR(moment / plastic_moment, 1.0, 0.01) << "bending direction " << angle << " deg";
    EXPECT_NEAR(r.resultants[0], 0.0, 1e-6 * 1540.0 * section.geometry().area);
  }
}

// Elastic-perfectly plastic disc: M(kappa) for kappa >= kappa_y, with the elastic core half-depth
// c = sigma_y / (E kappa): M = 4 sigma_y [ (1/c) int_0^c z^2 sqrt(r^2 - z^2) dz + (r^2 - c^2)^(3/2) / 3 ].
double disc_moment(double curvature, double radius, double E, double yield) {
  const double c = std::min(radius, yield / (E * curvature));
  const double core = (c / 8.0) * (2 * c * c - radius * radius) * std::sqrt(radius * radius - c * c) +
                      std::pow(radius, 4) / 8.0 * std::asin(c / radius);
  return 4.0 * yield * (core / c + std::pow(radius * radius - c * c, 1.5) / 3.0);
}

TEST(FibreSection, BentAndUnbentWireKeepsTheClosedFormResidualCurvature) {
  const double radius = 1.97, E = 188000, yield = 1540;
  const Material m = steel(0.0);
  const FibreSection section(SectionGeometry::circle(2 * radius, m.poisson_ratio), m);
  const double yield_curvature = yield / (E * radius);
  const double bent = 2.5 * yield_curvature;
  Vec6 strain = Vec6::Zero();
  strain[4] = bent;
  SectionHistory committed = section.initial_history(), trial;
  const SectionResponse loaded = section.evaluate(strain, committed, trial);
  const double expected_moment = disc_moment(bent, radius, E, yield);
  EXPECT_NEAR(loaded.resultants[4] / expected_moment, 1.0, 0.01);
  committed = trial;
  // Unload to zero moment by Newton on the curvature with the section tangent.
  for (int it = 0; it < 20; ++it) {
    const SectionResponse r = section.evaluate(strain, committed, trial);
    if (std::abs(r.resultants[4]) < 1e-9 * expected_moment) break;
    strain[4] -= r.resultants[4] / r.tangent(4, 4);
  }
  const double inertia = std::numbers::pi * std::pow(radius, 4) / 4.0;
  const double expected_residual = bent - expected_moment / (E * inertia);  // elastic unloading
  EXPECT_NEAR(strain[4] / expected_residual, 1.0, 0.015);
}

TEST(FibreSection, SectionTangentIsTheFiniteDifferenceOfTheResultants) {
  const Material m = steel(24600);
  const FibreSection section(SectionGeometry::circle(3.94, m.poisson_ratio), m);
  SectionHistory committed = section.initial_history(), trial;
  // A plastic state to start from: stretched past yield and bent, then a combined strain.
  Vec6 first;
  first << 0.011, 0.0, 0.0, 0.0, 0.002, -0.001;
  section.evaluate(first, committed, trial);
  committed = trial;
  Vec6 strain;
  strain << 0.012, 0.0004, -0.0003, 0.0015, 0.0025, -0.0005;
  const SectionResponse r = section.evaluate(strain, committed, trial);
  Mat6 fd;
  for (int k = 0; k < 6; ++k) {
    const double h = 1e-9;
    SectionHistory scratch;
    const Vec6 d = h * Vec6::Unit(k);
    fd.col(k) = (section.evaluate(strain + d, committed, scratch).resultants -
                 section.evaluate(strain - d, committed, scratch).resultants) / (2 * h);
  }
  EXPECT_LT((fd - r.tangent).norm(), 1e-6 * r.tangent.norm());
  EXPECT_GT(section.summary(strain, trial).max_plastic_strain, 0.0);
}

TEST(FibreSection, PlasticStateIsCommittedOrRevertedWithTheIncrement) {
  const Material m = steel(24600);
  const FibreSection section(SectionGeometry::circle(3.0, m.poisson_ratio), m);
  const auto reference = testing::helical_reference();
  BeamElement element({0, 1, 2}, &section, reference);
  BeamElementState element_state = element.initial_state();
  // Stretch the element 2 % along its chord: past yield.
  auto stretched = reference;
  for (auto& n : stretched) n.position *= 1.02;
  BeamElement::Output out;
  element.evaluate(stretched, element_state, true, out);
  const auto plastic = [&](const SectionHistory& h) { return std::abs(h.back()) > 0; };  // equivalent plastic strain
  EXPECT_TRUE(plastic(element_state.points[0].trial));
  element_state.revert();
  EXPECT_FALSE(plastic(element_state.points[0].trial));
  element.evaluate(stretched, element_state, true, out);
  element_state.commit();
  EXPECT_TRUE(plastic(element_state.points[0].committed));
  // The tangent of the element with yielding fibres is the finite difference of its residual.
  auto state = stretched;
  for (auto& n : state) n.position *= 1.001;
  element.evaluate(state, element_state, true, out);
  ElementMatrix fd;
  for (int k = 0; k < 18; ++k) {
    Eigen::Matrix<double, 18, 1> d = Eigen::Matrix<double, 18, 1>::Zero();
    d[k] = 1e-7;
    BeamElement::Output plus, minus;
    element.evaluate(testing::perturbed(state, d), element_state, false, plus);
    element.evaluate(testing::perturbed(state, -d), element_state, false, minus);
    fd.col(k) = (plus.residual - minus.residual) / 2e-7;
  }
  EXPECT_LT((fd - out.tangent).norm() / out.tangent.norm(), 1e-6);
}

}  // namespace
}  // namespace strandfem
