// A model's definition: mesh, beam elements, rigid ties, supports, load steps, contact and solver options.
#pragma once
#include <string>
#include <vector>

#include "strandfem/analysis/load_protocol.hpp"
#include "strandfem/beam/beam_element.hpp"
#include "strandfem/constraints/rigid_tie.hpp"
#include "strandfem/contact/contact_set.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

// Ceres-style options with documented defaults; validate() names the offending option.
struct SolverOptions {
  double force_tolerance = 0.005;         // ||force residual|| / reference force (paper: 0.5 %)
  double moment_tolerance = 0.005;        // ||moment residual|| / reference moment
  double displacement_tolerance = 0.005;  // ||last correction|| / ||increment displacement||
  // Every applied load is met to this fraction of the largest value it takes in its step (ConvergenceTest).
  double load_tolerance = 0.001;
  int max_iterations = 25;                // Newton iterations per increment before a cut-back
  int max_cutbacks = 8;                   // successive halvings of an increment before giving up
  int line_search_cuts = 0;               // halvings of a Newton correction that raises the residual (not an attempt's first)
  // Krylov reuse: GMRES on the current tangent, preconditioned by the last factorization, up to this many
  // iterations before refactoring (0: factor every Newton iteration); Newton keeps the exact tangent.
  int krylov_iterations = 12;
  // GMRES iterations that refine a solve with fresh single-precision factors (mumps_single) to krylov_tolerance;
  // when they do not suffice, the tangent is factored in double precision instead.
  int refinement_iterations = 30;
  double krylov_tolerance = 1e-8;         // relative residual of the linear solve
  // Inexact Newton: a correction's linear solve may stop at a relative residual of newton_forcing times the
  // Newton tolerance over the current relative residual (at most kMaxForcing, at least krylov_tolerance), so that
  // an iterate near convergence is confirmed with older factors; 0: every solve to krylov_tolerance.
  double newton_forcing = 0.2;
  // Predictor: start each increment of a step (after its first) from the converged state plus the last
  // increment's motion of the free DOFs, scaled to the new size, instead of moving the driven DOFs alone.
  bool extrapolate = true;
  // Viscous stabilization (ViscousStabilization): damping as a fraction of the elements' elastic stiffness (0: off),
  // constant over each step or ramped off linearly to zero at the step's end.
  double stabilization = 0;
  bool stabilization_ramp_off = true;
  // Recovery aid: when an increment cannot converge after its cut-backs, viscous (0.01) and contact (1e-4)
  // stabilization and line search switch on for the rest of the step, which goes on from a quarter of its nominal
  // increment.
  bool automatic_stabilization = true;
  std::string linear_solver = "mumps_single";  // mumps_single (single-precision factors refined by GMRES) | mumps | umfpack
  int threads = 0;                        // OpenMP threads for element evaluation; 0 = OpenMP default
  // Benchmark hook: the tangent of this factorization (counted from 1 in this invocation; 0: none) is written
  // to dump_tangent_path before it is factored (solver/tangent_dump.hpp, bench/tangent_bench).
  int dump_tangent_factorization = 0;
  std::string dump_tangent_path;
  void validate() const;                  // throws std::invalid_argument naming the bad option
};

// The definition of a model; its solution state (section and contact histories) is a ModelState.
struct Model {
  Mesh mesh;
  std::vector<BeamElement> elements;
  std::vector<RigidTie> ties;
  std::vector<Support> supports;
  std::vector<LoadStep> steps;
  SolverOptions options;
  ContactSettings contact_settings;  // contact.enabled = false: wires do not interact

  // Builds one BeamElement per mesh element from the mesh's reference configuration.
  void build_elements();
};

// Degrees of freedom: each node has 6; slave nodes of rigid ties have none of their own (their motion
// follows their master); supported and motion-driven DOFs are constrained (no equation).
struct DofMap {
  std::vector<int> tie_of;                    // node -> index into Model::ties, or -1
  std::vector<std::array<int, 6>> equation;   // node -> equation numbers, -1 if constrained or slave
  int equation_count = 0;

  int master_of(const Model& model, int node) const { return tie_of[node] < 0 ? node : model.ties[tie_of[node]].master; }
};

// Throws std::invalid_argument for supports or loads on tied nodes and for doubly-tied nodes.
DofMap build_dof_map(const Model& model);

}  // namespace strandfem
