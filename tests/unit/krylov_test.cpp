// GMRES against a direct solve: exact preconditioner in one iteration, an older factorization in a few, and an
// early stop when the preconditioner is too far off.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "strandfem/solver/krylov.hpp"

namespace strandfem {
namespace {

// Unsymmetric tridiagonal n x n matrix in CSC: diagonal d, sub-diagonal -1, super-diagonal -1 + skew.
SparsePattern tridiagonal(int n, std::vector<double>& values, double d, double skew) {
  SparsePattern p;
  p.size = n;
  p.column_start.push_back(0);
  for (int c = 0; c < n; ++c) {
    if (c > 0) p.row_index.push_back(c - 1), values.push_back(-1.0 + skew);
    p.row_index.push_back(c), values.push_back(d + 0.01 * c);
    if (c + 1 < n) p.row_index.push_back(c + 1), values.push_back(-1.0);
    p.column_start.push_back(static_cast<int>(p.row_index.size()));
  }
  return p;
}

TEST(Krylov, GmresWithAFactorizationOfANearbyMatrixConvergesInFewIterations) {
  const int n = 200;
  std::vector<double> current, older;
  const SparsePattern pattern = tridiagonal(n, current, 2.5, 0.3);
  tridiagonal(n, older, 2.4, 0.25);  // the "older tangent" whose factorization preconditions
  for (const std::string name : {"mumps", "umfpack"}) {
    auto solver = make_linear_solver(name);
    solver->analyze(pattern);
    solver->factorize(older);
    std::vector<double> expected(n), b;
    for (int i = 0; i < n; ++i) expected[i] = std::sin(0.1 * i) + 1.0;
    multiply(pattern, current, expected, b);
    std::vector<double> x;
    const KrylovResult r = gmres(pattern, current, [&](std::vector<double>& v) { solver->solve(v); }, b, x, 1e-12, 30);
    ASSERT_TRUE(r.converged) << name;
    EXPECT_LE(r.iterations, 12) << name;
    for (int i = 0; i < n; ++i) EXPECT_NEAR(x[i], expected[i], 1e-9) << name;
    // The exact factorization: one iteration.
    solver->factorize(current);
    const KrylovResult exact = gmres(pattern, current, [&](std::vector<double>& v) { solver->solve(v); }, b, x, 1e-12, 30);
    EXPECT_EQ(exact.iterations, 1) << name;
    // Too few iterations allowed: reported as not converged.
    solver->factorize(older);
    EXPECT_FALSE(gmres(pattern, current, [&](std::vector<double>& v) { solver->solve(v); }, b, x, 1e-14, 2).converged) << name;
  }
}

// A preconditioner far from the matrix (identity for a matrix of spread spectrum): after four iterations the
// mean reduction cannot reach the tolerance within the allowed count, so GMRES gives up instead of spending it.
TEST(Krylov, GmresGivesUpEarlyWhenTheProjectedReductionFallsShort) {
  const int n = 400;
  std::vector<double> values;
  const SparsePattern pattern = tridiagonal(n, values, 2.0, 0.0);
  std::vector<double> b(n), x;
  for (int i = 0; i < n; ++i) b[i] = std::sin(0.37 * i * i);
  const KrylovResult r = gmres(pattern, values, [](std::vector<double>&) {}, b, x, 1e-12, 60);
  EXPECT_FALSE(r.converged) << r.iterations << " " << r.relative_residual;
  EXPECT_LT(r.iterations, 60);
  EXPECT_GE(r.iterations, 4);
  // The same matrix with the tolerance reachable at its mean rate runs on.
  const KrylovResult loose = gmres(pattern, values, [](std::vector<double>&) {}, b, x, 0.5, 60);
  EXPECT_TRUE(loose.converged);
}

// The parallel product against the plain column loop, on a random pattern with empty columns and long ones: the
// same values to rounding, and the same bits whatever the thread count (the chunks are fixed, not per thread).
TEST(Krylov, ChunkedProductMatchesTheColumnLoopWhateverTheThreadCount) {
  const int n = 1000;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  SparsePattern pattern;
  pattern.size = n;
  pattern.column_start.push_back(0);
  std::vector<double> values;
  for (int c = 0; c < n; ++c) {
    const int count = c % 17 == 0 ? 0 : (c % 5 == 0 ? 200 : 7);
    for (int k = 0; k < count; ++k) {
      pattern.row_index.push_back((c * 31 + k * 97) % n);
      values.push_back(value(random));
    }
    std::sort(pattern.row_index.begin() + pattern.column_start.back(), pattern.row_index.end());
    pattern.row_index.erase(std::unique(pattern.row_index.begin() + pattern.column_start.back(), pattern.row_index.end()),
                            pattern.row_index.end());
    values.resize(pattern.row_index.size());
    pattern.column_start.push_back(static_cast<int>(pattern.row_index.size()));
  }
  std::vector<double> x(n);
  for (double& v : x) v = value(random);
  std::vector<double> reference(n, 0.0);
  for (int c = 0; c < n; ++c)
    for (int k = pattern.column_start[c]; k < pattern.column_start[c + 1]; ++k)
      reference[pattern.row_index[k]] += values[k] * x[c];
  const int threads = omp_get_max_threads();
  std::vector<std::vector<double>> products;
  for (int t : {1, 2, 3}) {
    omp_set_num_threads(t);
    std::vector<double> y;
    multiply(pattern, values, x, y);
    products.push_back(y);
  }
  omp_set_num_threads(threads);
  double scale = 0;
  for (double v : reference) scale = std::max(scale, std::abs(v));
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(products[0][i], reference[i], 1e-13 * scale) << i;
    EXPECT_EQ(products[1][i], products[0][i]) << i;
    EXPECT_EQ(products[2][i], products[0][i]) << i;
  }
}

}  // namespace
}  // namespace strandfem
