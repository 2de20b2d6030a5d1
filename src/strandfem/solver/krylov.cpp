#include "strandfem/solver/krylov.hpp"

#include <cmath>

#include <Eigen/Core>

namespace strandfem {
namespace {
constexpr int kIterationsBeforeProjection = 4;
}

void multiply(const SparsePattern& pattern, const std::vector<double>& values, const std::vector<double>& x,
              std::vector<double>& y) {
  ColumnChunkedProduct(pattern).apply(values, x, y);
}

ColumnChunkedProduct::ColumnChunkedProduct(const SparsePattern& pattern) : pattern_(pattern) {
  // Chunks of about equal entry counts; their number is fixed, so the sums do not depend on the thread count.
  const long long entries = pattern.column_start.empty() ? 0 : pattern.column_start[pattern.size];
  chunk_start_.assign(kChunks + 1, pattern.size);
  chunk_start_[0] = 0;
  int c = 0;
  for (int k = 1; k < kChunks; ++k) {
    while (c < pattern.size && pattern.column_start[c] < entries * k / kChunks) ++c;
    chunk_start_[k] = c;
  }
  partial_.assign(kChunks, std::vector<double>(pattern.size));
}

void ColumnChunkedProduct::apply(const std::vector<double>& values, const std::vector<double>& x,
                                 std::vector<double>& y) {
  const SparsePattern& p = pattern_;
  const int n = p.size;
  y.resize(n);
#pragma omp parallel
  {
#pragma omp for schedule(static, 1)
    for (int k = 0; k < kChunks; ++k) {
      std::vector<double>& part = partial_[k];
      std::fill(part.begin(), part.end(), 0.0);
      for (int c = chunk_start_[k]; c < chunk_start_[k + 1]; ++c) {
        const double xc = x[c];
        for (int e = p.column_start[c]; e < p.column_start[c + 1]; ++e) part[p.row_index[e]] += values[e] * xc;
      }
    }
#pragma omp for schedule(static)
    for (int r = 0; r < n; ++r) {
      double sum = 0;
      for (int k = 0; k < kChunks; ++k) sum += partial_[k][r];
      y[r] = sum;
    }
  }
}

KrylovResult gmres(const SparsePattern& pattern, const std::vector<double>& values,
                   const std::function<void(std::vector<double>&)>& precondition, const std::vector<double>& b,
                   std::vector<double>& x, double tolerance, int max_iterations) {
  const int n = pattern.size;
  KrylovResult result;
  x.assign(n, 0.0);
  using Vector = Eigen::VectorXd;
  const Vector rhs = Eigen::Map<const Vector>(b.data(), n);
  const double beta = rhs.norm();
  if (beta == 0.0) {
    result.converged = true;
    result.relative_residual = 0;
    return result;
  }
  // Arnoldi with modified Gram-Schmidt; Givens rotations keep the least-squares residual at hand.
  std::vector<Vector> basis{rhs / beta};
  Eigen::MatrixXd hessenberg = Eigen::MatrixXd::Zero(max_iterations + 1, max_iterations);
  Vector cosines(max_iterations), sines(max_iterations), g = Vector::Zero(max_iterations + 1);
  g[0] = beta;
  std::vector<double> work(n), product(n);
  // Flexible GMRES keeps z_k = M^-1 v_k and builds x from them: a single-precision preconditioner rounds its
  // input, so it is not exactly linear and M^-1 (V y) would differ from Z y by that rounding.
  std::vector<Vector> preconditioned;
  ColumnChunkedProduct product_of(pattern);
  int k = 0;
  for (; k < max_iterations; ++k) {
    Eigen::Map<Vector>(work.data(), n) = basis[k];
    precondition(work);
    preconditioned.push_back(Eigen::Map<const Vector>(work.data(), n));
    product_of.apply(values, work, product);
    Vector w = Eigen::Map<const Vector>(product.data(), n);
    for (int j = 0; j <= k; ++j) {
      hessenberg(j, k) = w.dot(basis[j]);
      w -= hessenberg(j, k) * basis[j];
    }
    const double next_norm = w.norm();
    hessenberg(k + 1, k) = next_norm;
    for (int j = 0; j < k; ++j) {
      const double t = cosines[j] * hessenberg(j, k) + sines[j] * hessenberg(j + 1, k);
      hessenberg(j + 1, k) = -sines[j] * hessenberg(j, k) + cosines[j] * hessenberg(j + 1, k);
      hessenberg(j, k) = t;
    }
    const double r = std::hypot(hessenberg(k, k), hessenberg(k + 1, k));
    cosines[k] = hessenberg(k, k) / r;
    sines[k] = hessenberg(k + 1, k) / r;
    hessenberg(k, k) = r;
    hessenberg(k + 1, k) = 0;
    g[k + 1] = -sines[k] * g[k];
    g[k] = cosines[k] * g[k];
    result.relative_residual = std::abs(g[k + 1]) / beta;
    if (result.relative_residual <= tolerance || !(next_norm > 0.0)) {
      ++k;
      break;
    }
    // Give up early when the mean reduction per iteration so far cannot reach the tolerance within the
    // allowed iterations: a preconditioner that far off costs solves and still ends in a refactorization.
    const int done = k + 1;
    if (done >= kIterationsBeforeProjection && done < max_iterations &&
        std::log(result.relative_residual) * max_iterations / done > std::log(tolerance)) {
      ++k;
      break;
    }
    basis.push_back(w / next_norm);
  }
  result.iterations = k;
  // x = Z y with H y = g (upper triangular after the rotations).
  const Vector y = hessenberg.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  Vector combination = Vector::Zero(n);
  for (int j = 0; j < k; ++j) combination += y[j] * preconditioned[j];
  Eigen::Map<Vector>(x.data(), n) = combination;
  result.converged = result.relative_residual <= tolerance && std::isfinite(result.relative_residual);
  return result;
}

}  // namespace strandfem
