// Times the linear algebra of a Newton correction on a real tangent written by `strandfem run --dump-tangent K`:
// single-precision MUMPS factorizations under two scalings (MUMPS' iterative one and the diagonal one the program
// uses), GMRES to 1e-8 on the double-precision tangent with those factors, and the tangent's matrix-vector
// product (plain column loop against the chunked parallel one), and the symbolic analysis (METIS ordering, and
// MUMPS' analysis of the equations' graph against that of the node blocks, ICNTL(15)). Variants run interleaved,
// so that a machine whose speed drifts during the run treats them alike. Usage: tangent_bench FILE [repeats], or
// `mpiexec --bind-to none -np P tangent_bench FILE [repeats]` for MUMPS on P processes. Figures: docs/performance.md.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "strandfem/solver/krylov.hpp"
#include "strandfem/solver/mumps_call.hpp"
#include "strandfem/solver/mumps_processes.hpp"
#include "strandfem/solver/tangent_dump.hpp"

using namespace strandfem;
using Clock = std::chrono::steady_clock;

namespace {
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Factors {
  SMUMPS_STRUC_C id{};
  int scaling = 0;  // ICNTL(8)
};

// The equations, their pivot order from libmetis, and zero values: what the program hands MUMPS for an analysis,
// which it does before the pattern's values exist.
struct Problem {
  const SparsePattern& pattern;
  std::vector<int> rows, cols, pivot_position;  // 1-based, as MUMPS reads them
  std::vector<float> zeros;
};

// An initialized single-precision MUMPS instance on the problem, with the program's controls and this scaling
// (ICNTL(8)); not analyzed yet.
void set_up(SMUMPS_STRUC_C& id, Problem& problem, int scaling) {
  id.comm_fortran = mumps_communicator();
  id.par = 1;
  id.sym = 0;
  id.job = -1;
  mumps_call(id);
  id.icntl[0] = id.icntl[1] = id.icntl[2] = -1;
  id.icntl[3] = 0;
  id.icntl[6] = 1;  // pivot order from libmetis, as the program does
  id.icntl[7] = scaling;
  id.icntl[13] = 50;
  id.n = problem.pattern.size;
  id.nnz = static_cast<MUMPS_INT8>(problem.rows.size());
  id.irn = problem.rows.data();
  id.jcn = problem.cols.data();
  id.a = problem.zeros.data();
  id.perm_in = problem.pivot_position.data();
}

// MUMPS' analysis (JOB = 1) on the graph of the equations or on that of the pattern's node blocks (ICNTL(15) = 1,
// as the program does); prints its time and estimated flops.
void time_analysis(Problem& problem, bool blocks) {
  std::vector<int> block_pointer(problem.pattern.block_start.begin(), problem.pattern.block_start.end());
  for (int& b : block_pointer) ++b;
  SMUMPS_STRUC_C id{};
  set_up(id, problem, 1);
  if (blocks && block_pointer.size() > 1) {
    id.icntl[14] = 1;
    id.nblk = static_cast<int>(block_pointer.size()) - 1;
    id.blkptr = block_pointer.data();
  }
  const auto start = Clock::now();
  id.job = 1;
  mumps_call(id);
  std::printf("analysis on the graph of %s: %.3f s (INFOG(1) %d, estimated flops %.4g)\n",
              blocks ? "node blocks (ICNTL(15) = 1)" : "equations", seconds_since(start), id.infog[0], id.rinfog[0]);
  id.job = -2;
  mumps_call(id);
}

void column_loop_product(const SparsePattern& p, const std::vector<double>& a, const std::vector<double>& x,
                         std::vector<double>& y) {
  y.assign(p.size, 0.0);
  for (int c = 0; c < p.size; ++c)
    for (int k = p.column_start[c]; k < p.column_start[c + 1]; ++k) y[p.row_index[k]] += a[k] * x[c];
}
}  // namespace

int main(int argc, char** argv) {
  // Under `mpiexec -np P` (MPI build) the factorizations and solves run on P processes, as in the program.
  MumpsProcesses processes(argc, argv);
  if (processes.rank() > 0) return processes.serve();
  if (argc < 2) {
    std::fprintf(stderr, "usage: tangent_bench FILE [repeats]\n");
    return 2;
  }
  const int repeats = argc > 2 ? std::stoi(argv[2]) : 3;
  const StoredTangent t = read_tangent(argv[1]);
  const SparsePattern& p = t.pattern;
  std::printf("%s: %d equations, %zu entries, %d OpenMP threads, MUMPS %s on %d processes\n", argv[1], p.size,
              p.nonzeros(), omp_get_max_threads(), mumps_build().c_str(), processes.count());
  Problem problem{p, {}, {}, {}, std::vector<float>(p.nonzeros(), 0.0f)};
  for (int c = 0; c < p.size; ++c)
    for (int k = p.column_start[c]; k < p.column_start[c + 1]; ++k)
      problem.rows.push_back(p.row_index[k] + 1), problem.cols.push_back(c + 1);
  auto ordering_start = Clock::now();
  problem.pivot_position = nested_dissection_ordering(p);
  std::printf("METIS nested dissection of the block graph: %.3f s\n", seconds_since(ordering_start));
  for (int& q : problem.pivot_position) ++q;
  std::vector<float> values(t.values.begin(), t.values.end());
  for (int r = 0; r < repeats; ++r)
    for (bool blocks : {false, true}) time_analysis(problem, blocks);
  std::vector<Factors> variants(2);
  variants[0].scaling = 7;  // MUMPS' default choice for this matrix (77 picks it)
  variants[1].scaling = 1;  // diagonal: what strandfem's single-precision solver sets
  for (Factors& f : variants) {
    set_up(f.id, problem, f.scaling);
    f.id.job = 1;
    mumps_call(f.id);
    f.id.a = values.data();
  }
  std::vector<double> b(p.size), x;
  for (int i = 0; i < p.size; ++i) b[i] = std::sin(0.1 * i) + 0.5;
  for (int r = 0; r < repeats; ++r)
    for (Factors& f : variants) {
      SMUMPS_STRUC_C& id = f.id;
      auto start = Clock::now();
      id.job = 2;
      mumps_call(id);
      const double factorization = seconds_since(start);
      std::vector<float> rhs;
      start = Clock::now();
      const KrylovResult k = gmres(
          p, t.values,
          [&](std::vector<double>& v) {
            rhs.assign(v.begin(), v.end());
            id.rhs = rhs.data();
            id.nrhs = 1;
            id.lrhs = p.size;
            id.job = 3;
            mumps_call(id);
            v.assign(rhs.begin(), rhs.end());
          },
          b, x, 1e-8, 30);
      std::printf("scaling ICNTL(8) = %d: factorization %.3f s (%.3g flops, INFOG(1) %d), GMRES %d iterations to %.2g in %.3f s\n",
                  f.scaling, factorization, id.rinfog[2], id.infog[0], k.iterations, k.relative_residual, seconds_since(start));
    }
  std::vector<double> v(p.size), y;
  for (int i = 0; i < p.size; ++i) v[i] = std::cos(0.3 * i);
  ColumnChunkedProduct chunked(p);
  const int products = 20;
  for (int r = 0; r < repeats; ++r) {
    auto start = Clock::now();
    for (int i = 0; i < products; ++i) column_loop_product(p, t.values, v, y);
    const double plain = seconds_since(start) / products;
    start = Clock::now();
    for (int i = 0; i < products; ++i) chunked.apply(t.values, v, y);
    std::printf("matrix-vector product: column loop %.4f s, chunked %.4f s\n", plain, seconds_since(start) / products);
  }
  for (Factors& f : variants) {
    f.id.job = -2;
    mumps_call(f.id);
  }
  return 0;
}
