// Requirement: the assembled tangent (elements, rigid end ties, spin updates) is the exact derivative of
// the assembled residual, so Newton converges quadratically.
#include "strandfem/solver/assembler.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "strandfem/io/case_file.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {
namespace {

// Assembled tangent on free DOFs as a dense matrix.
Eigen::MatrixXd dense(const SparsePattern& p, const std::vector<double>& values) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(p.size, p.size);
  for (int c = 0; c < p.size; ++c)
    for (int k = p.column_start[c]; k < p.column_start[c + 1]; ++k) K(p.row_index[k], c) = values[k];
  return K;
}

// Residual on free DOFs after perturbing free DOF `eq` by h (spin for rotations), slaves following.
Eigen::VectorXd free_residual(const Model& model, ModelState& model_state, const DofMap& dofs, Assembler& assembler,
                              std::vector<NodeState> state, int eq, double h) {
  for (std::size_t n = 0; n < state.size(); ++n)
    for (int c = 0; c < 6; ++c)
      if (dofs.equation[n][c] == eq) {
        if (c < 3) state[n].position[c] += h;
        else state[n].rotation = quaternion_from_rotation_vector(h * Vec3::Unit(c - 3)) * state[n].rotation;
      }
  for (const RigidTie& t : model.ties) state[t.slave] = tied_state(t, state[t.master]);
  std::vector<double> forces;
  assembler.assemble(model, model_state, state, forces, nullptr);
  Eigen::VectorXd r(dofs.equation_count);
  for (std::size_t n = 0; n < state.size(); ++n)
    for (int c = 0; c < 6; ++c)
      if (dofs.equation[n][c] >= 0) r[dofs.equation[n][c]] = forces[6 * n + c];
  return r;
}

// `contact` is appended to the case: the tangent must stay exact with frictional contacts on tied nodes.
void check_tied_strand_tangent(const std::string& contact,
                               const std::string& material = "{steel: {E: 188000, nu: 0.3}}") {
  const std::string path = ::testing::TempDir() + "/tied_strand.yaml";
  std::ofstream(path) << contact << R"(
title: small tied strand
materials: )" + material + R"(
strand:
  length: 30
  ends: free
  layers:
    - {wires: 1, diameter: 3.94, material: steel}
    - {wires: 6, diameter: 3.73, material: steel, lay_angle: 11.8}
mesh: {elements_per_wire: 2}
steps:
  - {increments: 2, axial_strain: 0.02, torque: 2000}
solver: {force_tolerance: 1.0e-8, moment_tolerance: 1.0e-8}
)";
  CaseDefinition c = load_case(path);
  StaticAnalysis analysis(c.model);
  ASSERT_TRUE(analysis.run({}).converged);
  double plastic_strain = 0;
  for (std::size_t k = 0; k < c.model.elements.size(); ++k)
    for (const SectionPointState& p : analysis.model_state().elements[k].points)
      plastic_strain = std::max(plastic_strain, c.model.elements[k].section().summary(p.strain, p.committed).max_plastic_strain);
  if (material.find("plasticity") != std::string::npos) EXPECT_GT(plastic_strain, 1e-3) << "the check must run past yield";
  // Disturb the converged state so the check runs away from equilibrium, where asymmetric terms show.
  std::vector<NodeState> state = analysis.state();
  for (std::size_t n = 0; n < state.size(); ++n) {
    state[n].position += 0.01 * Vec3(std::sin(n), std::cos(2.0 * n), std::sin(3.0 * n));
    state[n].rotation = quaternion_from_rotation_vector(0.02 * Vec3(std::cos(n), std::sin(n), 0.5)) * state[n].rotation;
  }
  for (const RigidTie& t : c.model.ties) state[t.slave] = tied_state(t, state[t.master]);
  const DofMap& dofs = analysis.dofs();
  // A copy of the converged model state: the finite differences write trial histories into it.
  ModelState model_state = analysis.model_state();
  Assembler assembler(c.model, model_state, dofs);
  std::vector<double> forces, values;
  assembler.assemble(c.model, model_state, state, forces, &values);
  const Eigen::MatrixXd K = dense(assembler.pattern(), values);
  Eigen::MatrixXd fd(dofs.equation_count, dofs.equation_count);
  const double h = 1e-6;
  for (int eq = 0; eq < dofs.equation_count; ++eq)
    fd.col(eq) = (free_residual(c.model, model_state, dofs, assembler, state, eq, h) -
                  free_residual(c.model, model_state, dofs, assembler, state, eq, -h)) / (2 * h);
  EXPECT_LT((fd - K).norm() / K.norm(), 1e-6);
  if (c.model.contact_settings.enabled) {
    int closed = 0, frictional = 0;
    for (std::size_t i = 0; i < model_state.contacts.points().size(); ++i) {
      const bool is_closed = model_state.contacts.responses()[i].status != ContactStatus::kOpen;
      closed += is_closed;
      frictional += is_closed && model_state.contacts.points()[i].history.anchored && model_state.contacts.points()[i].mu1 > 0;
    }
    EXPECT_GT(closed, 0) << "the check must run with closed contacts";
    if (c.model.contact_settings.friction > 0) EXPECT_GT(frictional, 0) << "and with surface friction (stick anchors set)";
  }
}

TEST(AssemblyTest, TiedStrandTangentMatchesFiniteDifferences) { check_tied_strand_tangent(""); }

// Surface friction: the spins of both wires enter the tangential gap and the friction moments.
TEST(AssemblyTest, TiedStrandWithFrictionalContactTangentMatchesFiniteDifferences) {
  check_tied_strand_tangent("contact: {friction: 0.3}\n");
  check_tied_strand_tangent("contact: {friction: 0.3, tangential_penalty: paper}\n");
}

// Elastoplastic wires pulled to 2 % (past yield) with frictional contact: the fibre sections' consistent
// tangents inside the assembled one.
TEST(AssemblyTest, TiedElastoplasticStrandWithFrictionalContactTangentMatchesFiniteDifferences) {
  check_tied_strand_tangent("contact: {friction: 0.3}\n",
                            "{steel: {E: 188000, nu: 0.3, plasticity: {yield_stress: 1540, tangent_modulus: 5500}}}");
}

}  // namespace
}  // namespace strandfem
