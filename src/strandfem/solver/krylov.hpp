// Flexible GMRES (right-preconditioned, no restart) on a CSC matrix: solves the current tangent with an older
// factorization, or single-precision factors, as preconditioner, so that Newton keeps the exact tangent's
// convergence without refactoring every iteration.
#pragma once
#include <functional>
#include <vector>

#include "strandfem/solver/linear_solver.hpp"

namespace strandfem {

struct KrylovResult {
  bool converged = false;
  int iterations = 0;             // preconditioned matrix-vector products
  double relative_residual = 1;   // ||b - A x|| / ||b|| at the end (the true residual: right preconditioning)
};

// y = A x for A in `pattern` with `values`.
void multiply(const SparsePattern& pattern, const std::vector<double>& values, const std::vector<double>& x,
              std::vector<double>& y);

// y = A x in parallel over fixed chunks of columns, each summed into its own vector and the chunks added in
// their order: the sums do not depend on the thread count. Holds its work vectors for repeated products.
class ColumnChunkedProduct {
 public:
  explicit ColumnChunkedProduct(const SparsePattern& pattern);
  void apply(const std::vector<double>& values, const std::vector<double>& x, std::vector<double>& y);

 private:
  static constexpr int kChunks = 4;
  const SparsePattern& pattern_;
  std::vector<int> chunk_start_;
  std::vector<std::vector<double>> partial_;
};

// Solves A x = b from x = 0; `precondition` overwrites its argument v with M^-1 v. Stops when
// ||b - A x|| <= tolerance ||b|| or after max_iterations (no restart: the preconditioner is meant to be good).
KrylovResult gmres(const SparsePattern& pattern, const std::vector<double>& values,
                   const std::function<void(std::vector<double>&)>& precondition, const std::vector<double>& b,
                   std::vector<double>& x, double tolerance, int max_iterations);

}  // namespace strandfem
