// UMFPACK (SuiteSparse) unsymmetric multifrontal LU with METIS ordering.
#include <umfpack.h>

#include <string>

#include "strandfem/solver/linear_solver.hpp"

namespace strandfem {
namespace {

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver() {
    umfpack_di_defaults(control_);
    // METIS ordering was 3-7x faster than AMD on strand tangents (docs/performance.md).
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  }
  ~UmfpackSolver() override { release(); }

  void analyze(const SparsePattern& pattern) override {
    release();
    pattern_ = pattern;
    const int status = umfpack_di_symbolic(pattern_.size, pattern_.size, pattern_.column_start.data(),
                                           pattern_.row_index.data(), nullptr, &symbolic_, control_, info_);
    if (status != UMFPACK_OK) throw LinearSolverError("UMFPACK symbolic analysis failed, status " + std::to_string(status));
  }

  void factorize(const std::vector<double>& values) override {
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    values_ = values;
    const int status = umfpack_di_numeric(pattern_.column_start.data(), pattern_.row_index.data(), values_.data(),
                                          symbolic_, &numeric_, control_, info_);
    if (status != UMFPACK_OK) throw LinearSolverError("UMFPACK factorization failed (singular or unstable tangent), status " + std::to_string(status));
  }

  void solve(std::vector<double>& rhs) override {
    std::vector<double> x(rhs.size());
    const int status = umfpack_di_solve(UMFPACK_A, pattern_.column_start.data(), pattern_.row_index.data(),
                                        values_.data(), x.data(), rhs.data(), numeric_, control_, info_);
    if (status != UMFPACK_OK) throw LinearSolverError("UMFPACK solve failed, status " + std::to_string(status));
    rhs.swap(x);
  }

  std::string name() const override { return "umfpack"; }

 private:
  void release() {
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  }
  SparsePattern pattern_;
  std::vector<double> values_;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  double control_[UMFPACK_CONTROL];
  double info_[UMFPACK_INFO];
};

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

}  // namespace strandfem
