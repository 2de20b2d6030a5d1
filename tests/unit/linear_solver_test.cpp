// Requirement: both sparse direct solvers solve unsymmetric systems to round-off, order with METIS for
// real (read back from the solver, not assumed from the request) and report their statistics.
#include "strandfem/solver/linear_solver.hpp"
#include "strandfem/solver/krylov.hpp"
#include "strandfem/solver/blas_kernels.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace strandfem {
namespace {

constexpr int kGrid = 20;  // 20 x 20 grid: 400 unknowns
constexpr int kUnknowns = kGrid * kGrid;

// A CSC matrix: pattern and the values laid out as it.
struct SparseMatrix {
  SparsePattern pattern;
  std::vector<double> values;
};

// 5-point Laplacian plus a central-difference convection term on a kGrid x kGrid grid: unsymmetric values on
// a symmetric pattern, like a frictional tangent; diagonally dominant, hence well conditioned.
SparseMatrix convection_diffusion_matrix() {
  std::map<std::pair<int, int>, double> entries;  // (col, row) -> value, in CSC order
  auto unknown = [](int i, int j) { return i * kGrid + j; };
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const int row = unknown(i, j);
      entries[{row, row}] = 4.0;
      if (i > 0) entries[{unknown(i - 1, j), row}] = -1.0 - 0.25;
      if (i + 1 < kGrid) entries[{unknown(i + 1, j), row}] = -1.0 + 0.25;
      if (j > 0) entries[{unknown(i, j - 1), row}] = -1.0 - 0.4;
      if (j + 1 < kGrid) entries[{unknown(i, j + 1), row}] = -1.0 + 0.4;
    }
  SparseMatrix a;
  a.pattern.size = kUnknowns;
  a.pattern.column_start.assign(kUnknowns + 1, 0);
  for (const auto& [col_row, value] : entries) {
    ++a.pattern.column_start[col_row.first + 1];
    a.pattern.row_index.push_back(col_row.second);
    a.values.push_back(value);
  }
  for (int c = 0; c < kUnknowns; ++c) a.pattern.column_start[c + 1] += a.pattern.column_start[c];
  return a;
}

std::vector<double> multiply(const SparseMatrix& a, const std::vector<double>& x) {
  std::vector<double> y(a.pattern.size, 0.0);
  for (int c = 0; c < a.pattern.size; ++c)
    for (int k = a.pattern.column_start[c]; k < a.pattern.column_start[c + 1]; ++k)
      y[a.pattern.row_index[k]] += a.values[k] * x[c];
  return y;
}

std::vector<double> known_solution() {
  std::vector<double> x(kUnknowns);
  for (int k = 0; k < kUnknowns; ++k) x[k] = 1.0 + std::sin(0.37 * k);
  return x;
}

// Factors and solves A x = A x_known, and checks x against x_known and the statistics of one call each.
void check_solver(const std::string& name, const std::string& expected_ordering) {
  SCOPED_TRACE(name);
  const SparseMatrix a = convection_diffusion_matrix();
  const std::vector<double> expected = known_solution();
  auto solver = make_linear_solver(name);
  solver->analyze(a.pattern);
  solver->factorize(a.values);
  std::vector<double> x = multiply(a, expected);
  solver->solve(x);
  for (int k = 0; k < kUnknowns; ++k) ASSERT_NEAR(x[k], expected[k], 1e-10) << "unknown " << k;

  const LinearSolverStatistics& statistics = solver->statistics();
  EXPECT_EQ(statistics.ordering, expected_ordering);
  EXPECT_EQ(statistics.analyses, 1);
  EXPECT_EQ(statistics.factorizations, 1);
  EXPECT_EQ(statistics.solves, 1);
  EXPECT_GE(statistics.factor_entries, static_cast<long long>(a.pattern.nonzeros()));
  // A band LU in the natural order (half-bandwidth kGrid) stores about 2 kGrid entries per unknown; a nested
  // dissection must do clearly better. An inverted permutation (pivot order passed where positions are
  // expected) breaks this bound.
  EXPECT_LT(statistics.factor_entries, 2LL * kGrid * kUnknowns);
  EXPECT_GT(statistics.factorization_flops, 0.0);
  EXPECT_GE(statistics.analysis_seconds, 0.0);
  EXPECT_GE(statistics.factorization_seconds, 0.0);
  EXPECT_GE(statistics.solve_seconds, 0.0);
}

TEST(LinearSolverTest, MumpsSolvesUnsymmetricSystemWithMetisOrdering) {
  // INFOG(7) = 1: MUMPS ran the pivot order computed with libmetis (its own METIS is absent on Debian).
  check_solver("mumps", "metis (user-supplied via libmetis)");
}

TEST(LinearSolverTest, UmfpackSolvesUnsymmetricSystemWithMetisOrdering) { check_solver("umfpack", "metis"); }

// Single-precision factors solve to single precision only (so they say they need refinement); as the
// preconditioner of GMRES on the double-precision matrix they give the solution to round-off in a few iterations.
TEST(LinearSolverTest, SinglePrecisionMumpsPreconditionsGmresToDoublePrecision) {
  const SparseMatrix a = convection_diffusion_matrix();
  const std::vector<double> expected = known_solution();
  auto solver = make_linear_solver("mumps_single");
  EXPECT_TRUE(solver->needs_refinement());
  EXPECT_FALSE(make_linear_solver("mumps")->needs_refinement());
  solver->analyze(a.pattern);
  solver->factorize(a.values);
  const std::vector<double> b = multiply(a, expected);
  std::vector<double> direct = b;
  solver->solve(direct);
  double direct_error = 0;
  for (int k = 0; k < kUnknowns; ++k) direct_error = std::max(direct_error, std::abs(direct[k] - expected[k]));
  EXPECT_GT(direct_error, 1e-12);  // single precision shows
  EXPECT_LT(direct_error, 1e-4);
  std::vector<double> x;
  const KrylovResult k = gmres(a.pattern, a.values, [&](std::vector<double>& v) { solver->solve(v); }, b, x, 1e-13, 10);
  EXPECT_TRUE(k.converged);
  EXPECT_LE(k.iterations, 4);
  for (int i = 0; i < kUnknowns; ++i) ASSERT_NEAR(x[i], expected[i], 1e-11) << "unknown " << i;
  EXPECT_EQ(solver->statistics().ordering, "metis (user-supplied via libmetis)");
}

TEST(LinearSolverTest, NestedDissectionOrderingIsAPermutation) {
  const SparseMatrix a = convection_diffusion_matrix();
  std::vector<int> position = nested_dissection_ordering(a.pattern);
  ASSERT_EQ(static_cast<int>(position.size()), kUnknowns);
  std::sort(position.begin(), position.end());
  for (int k = 0; k < kUnknowns; ++k) EXPECT_EQ(position[k], k);
}

TEST(LinearSolverTest, NestedDissectionOrdersTheSymmetrizedPattern) {
  // Either triangle alone has the same A + A^T graph as the whole matrix, so the same METIS ordering.
  const SparseMatrix a = convection_diffusion_matrix();
  SparsePattern lower, upper;
  lower.size = upper.size = a.pattern.size;
  lower.column_start = upper.column_start = {0};
  for (int c = 0; c < a.pattern.size; ++c) {
    for (int k = a.pattern.column_start[c]; k < a.pattern.column_start[c + 1]; ++k) {
      const int row = a.pattern.row_index[k];
      if (row >= c) lower.row_index.push_back(row);
      if (row <= c) upper.row_index.push_back(row);
    }
    lower.column_start.push_back(static_cast<int>(lower.row_index.size()));
    upper.column_start.push_back(static_cast<int>(upper.row_index.size()));
  }
  const std::vector<int> expected = nested_dissection_ordering(a.pattern);
  EXPECT_EQ(nested_dissection_ordering(lower), expected);
  EXPECT_EQ(nested_dissection_ordering(upper), expected);
}

// A node's DOFs share their couplings: ordered as blocks (the graph is 36 times smaller for 6 DOFs per node), they
// stay together in the pivot order, each block's in its own order.
TEST(LinearSolverTest, NestedDissectionKeepsEachBlockTogether) {
  const SparseMatrix grid = convection_diffusion_matrix();
  constexpr int kBlock = 3;
  SparsePattern blocked;
  blocked.size = kBlock * kUnknowns;
  blocked.column_start = {0};
  for (int c = 0; c < kUnknowns; ++c)
    for (int i = 0; i < kBlock; ++i) {
      for (int k = grid.pattern.column_start[c]; k < grid.pattern.column_start[c + 1]; ++k)
        for (int j = 0; j < kBlock; ++j) blocked.row_index.push_back(kBlock * grid.pattern.row_index[k] + j);
      blocked.column_start.push_back(static_cast<int>(blocked.row_index.size()));
    }
  for (int b = 0; b <= kUnknowns; ++b) blocked.block_start.push_back(kBlock * b);
  const std::vector<int> position = nested_dissection_ordering(blocked);
  std::vector<int> sorted = position;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < blocked.size; ++k) ASSERT_EQ(sorted[k], k);
  for (int b = 0; b < kUnknowns; ++b) {
    EXPECT_EQ(position[kBlock * b] % kBlock, 0) << "block " << b;
    for (int j = 1; j < kBlock; ++j) EXPECT_EQ(position[kBlock * b + j], position[kBlock * b] + j) << "block " << b;
  }
  blocked.block_start = {0, 5, 4, blocked.size};
  EXPECT_THROW(nested_dissection_ordering(blocked), std::invalid_argument);
  blocked.block_start = {0, 3, 3, blocked.size};  // an empty block
  EXPECT_THROW(nested_dissection_ordering(blocked), std::invalid_argument);
}

TEST(LinearSolverTest, StatisticsAccumulateOverRepeatedCalls) {
  const SparseMatrix a = convection_diffusion_matrix();
  auto solver = make_linear_solver("mumps");
  solver->analyze(a.pattern);
  for (int repeat = 0; repeat < 2; ++repeat) {
    solver->factorize(a.values);
    for (int right_hand_side = 0; right_hand_side < 3; ++right_hand_side) {
      std::vector<double> x(kUnknowns, 1.0);
      solver->solve(x);
    }
  }
  EXPECT_EQ(solver->statistics().analyses, 1);
  EXPECT_EQ(solver->statistics().factorizations, 2);
  EXPECT_EQ(solver->statistics().solves, 6);
}

// OpenBLAS' AVX2 kernels are replaced by its SkylakeX ones only where it took an AVX-512 CPU for Haswell or Zen,
// and never against a core type the user chose.
TEST(BlasKernels, SkylakeXKernelsOnlyWhereOpenBlasMissedTheCpusAvx512) {
  EXPECT_EQ(preferred_openblas_core("Haswell", true, false), "SkylakeX");
  EXPECT_EQ(preferred_openblas_core("Zen", true, false), "SkylakeX");
  EXPECT_EQ(preferred_openblas_core("Haswell", false, false), "");   // an AVX2-only CPU: Haswell is right
  EXPECT_EQ(preferred_openblas_core("Haswell", true, true), "");     // OPENBLAS_CORETYPE set by the user
  EXPECT_EQ(preferred_openblas_core("SkylakeX", true, false), "");   // recognized already
  EXPECT_EQ(preferred_openblas_core("SapphireRapids", true, false), "");
  EXPECT_EQ(preferred_openblas_core("not OpenBLAS", true, false), "");
  EXPECT_FALSE(blas_core_name().empty());
}

}  // namespace
}  // namespace strandfem
