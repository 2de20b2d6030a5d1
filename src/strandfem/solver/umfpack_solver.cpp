// UMFPACK (SuiteSparse) unsymmetric multifrontal LU with METIS ordering.
#include <umfpack.h>

#include <chrono>
#include <string>

#include "strandfem/solver/linear_solver.hpp"

namespace strandfem {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Name of the ordering UMFPACK reports in Info[UMFPACK_ORDERING_USED] after symbolic analysis.
std::string ordering_name(double used) {
  switch (static_cast<int>(used)) {
    case UMFPACK_ORDERING_AMD: return "amd/colamd";  // AMD for the symmetric strategy, COLAMD otherwise
    case UMFPACK_ORDERING_GIVEN: return "given";
    case UMFPACK_ORDERING_METIS: return "metis";
    case UMFPACK_ORDERING_NONE: return "natural";
    case UMFPACK_ORDERING_USER: return "user";
    default: return "unknown (Info[UMFPACK_ORDERING_USED] = " + std::to_string(used) + ")";
  }
}

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver() {
    umfpack_di_defaults(control_);
    // METIS, as for MUMPS (on contact-free strand tangents the ordering barely matters: docs/performance.md).
    // Debian's UMFPACK reaches METIS through CHOLMOD, and the ordering read back after analysis confirms it ran.
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  }
  ~UmfpackSolver() override { release(); }

  void analyze(const SparsePattern& pattern) override {
    const auto start = Clock::now();
    release();
    pattern_ = pattern;
    const int status = umfpack_di_symbolic(pattern_.size, pattern_.size, pattern_.column_start.data(),
                                           pattern_.row_index.data(), nullptr, &symbolic_, control_, info_);
    if (status != UMFPACK_OK) throw LinearSolverError("UMFPACK symbolic analysis failed, status " + std::to_string(status));
    statistics_.ordering = ordering_name(info_[UMFPACK_ORDERING_USED]);
    ++statistics_.analyses;
    statistics_.analysis_seconds += seconds_since(start);
  }

  void factorize(const std::vector<double>& values) override {
    const auto start = Clock::now();
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    values_ = values;
    const int status = umfpack_di_numeric(pattern_.column_start.data(), pattern_.row_index.data(), values_.data(),
                                          symbolic_, &numeric_, control_, info_);
    if (status != UMFPACK_OK) throw LinearSolverError("UMFPACK factorization failed (singular or unstable tangent), status " + std::to_string(status));
    // L and U both count the diagonal; keep it once, as in a combined LU factor.
    statistics_.factor_entries =
        static_cast<long long>(info_[UMFPACK_LNZ] + info_[UMFPACK_UNZ]) - pattern_.size;
    statistics_.factorization_flops = info_[UMFPACK_FLOPS];
    ++statistics_.factorizations;
    statistics_.factorization_seconds += seconds_since(start);
  }

  void solve(std::vector<double>& rhs) override {
    const auto start = Clock::now();
    std::vector<double> x(rhs.size());
    const int status = umfpack_di_solve(UMFPACK_A, pattern_.column_start.data(), pattern_.row_index.data(),
                                        values_.data(), x.data(), rhs.data(), numeric_, control_, info_);
    if (status != UMFPACK_OK) throw LinearSolverError("UMFPACK solve failed, status " + std::to_string(status));
    rhs.swap(x);
    ++statistics_.solves;
    statistics_.solve_seconds += seconds_since(start);
  }

  std::string name() const override { return "umfpack"; }
  const LinearSolverStatistics& statistics() const override { return statistics_; }

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
  LinearSolverStatistics statistics_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

}  // namespace strandfem
