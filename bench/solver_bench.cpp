// Times the sparse direct solvers (analyze, factorize, solve) and the tangent assembly on strand tangents.
// Usage: solver_bench CASE.yaml [repeats]. Run on demand; figures go to docs/performance.md.
#include <chrono>
#include <cstdio>
#include <string>

#include "strandfem/io/case_file.hpp"
#include "strandfem/solver/assembler.hpp"

using namespace strandfem;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: solver_bench CASE.yaml [repeats]\n");
    return 2;
  }
  const int repeats = argc > 2 ? std::stoi(argv[2]) : 3;
  CaseDefinition c = load_case(argv[1]);
  c.model.build_elements();
  const DofMap dofs = build_dof_map(c.model);
  ModelState model_state = ModelState::initial(c.model);  // contacts not initialized: the tied strand alone
  Assembler assembler(c.model, model_state, dofs);
  // A slightly stretched and twisted state, so the tangent has its geometric terms.
  std::vector<NodeState> state;
  for (const MeshNode& n : c.model.mesh.nodes) {
    NodeState s = n.reference;
    s.position.z() *= 1.002;
    s.rotation = quaternion_from_rotation_vector(Vec3(0, 0, 1e-4 * n.reference.position.z())) * s.rotation;
    state.push_back(s);
  }
  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a) { return std::chrono::duration<double>(clock::now() - a).count(); };
  std::vector<double> forces, values;
  double assemble_time = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t = clock::now();
    assembler.assemble(c.model, model_state, state, forces, &values);
    assemble_time = std::min(assemble_time, seconds(t));
  }
  std::printf("case %s: %d DOFs, %zu nonzeros, %zu elements\n", argv[1], dofs.equation_count,
              assembler.pattern().nonzeros(), c.model.elements.size());
  std::printf("assembly (residual + tangent): %.3f s\n", assemble_time);
  for (const char* name : {"mumps", "umfpack"}) {
    auto solver = make_linear_solver(name);
    double analyze = 1e30, factorize = 1e30, solve = 1e30;
    for (int r = 0; r < repeats; ++r) {
      auto t = clock::now();
      solver->analyze(assembler.pattern());
      analyze = std::min(analyze, seconds(t));
      t = clock::now();
      solver->factorize(values);
      factorize = std::min(factorize, seconds(t));
      std::vector<double> rhs(dofs.equation_count, 1.0);
      t = clock::now();
      solver->solve(rhs);
      solve = std::min(solve, seconds(t));
    }
    std::printf("%-8s analyze %.3f s  factorize %.3f s  solve %.3f s\n", name, analyze, factorize, solve);
  }
  return 0;
}
