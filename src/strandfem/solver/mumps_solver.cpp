// MUMPS 5.5 sequential unsymmetric multifrontal LU with METIS ordering (the path to distributed runs).
#include <dmumps_c.h>

#include <string>

#include "strandfem/solver/linear_solver.hpp"

namespace strandfem {
namespace {

constexpr int kUseCommWorld = -987654;  // MUMPS' Fortran communicator placeholder for the sequential build

class MumpsSolver final : public LinearSolver {
 public:
  MumpsSolver() {
    id_.comm_fortran = kUseCommWorld;
    id_.par = 1;
    id_.sym = 0;  // unsymmetric: friction makes the tangent unsymmetric
    id_.job = -1;
    dmumps_c(&id_);
    check("initialization");
    id_.icntl[0] = -1;  // no error messages on stdout: errors are reported through exceptions
    id_.icntl[1] = -1;
    id_.icntl[2] = -1;
    id_.icntl[3] = 0;
    id_.icntl[6] = 5;    // ICNTL(7) = 5: METIS ordering
    id_.icntl[13] = 50;  // ICNTL(14): 50 % working-space relaxation
  }
  ~MumpsSolver() override {
    id_.job = -2;
    dmumps_c(&id_);
  }

  void analyze(const SparsePattern& pattern) override {
    rows_.clear();
    cols_.clear();
    for (int c = 0; c < pattern.size; ++c)
      for (int k = pattern.column_start[c]; k < pattern.column_start[c + 1]; ++k) {
        rows_.push_back(pattern.row_index[k] + 1);
        cols_.push_back(c + 1);
      }
    values_.assign(rows_.size(), 0.0);
    id_.n = pattern.size;
    id_.nnz = static_cast<MUMPS_INT8>(rows_.size());
    id_.irn = rows_.data();
    id_.jcn = cols_.data();
    id_.a = values_.data();
    id_.job = 1;
    dmumps_c(&id_);
    check("analysis");
  }

  void factorize(const std::vector<double>& values) override {
    values_ = values;
    id_.a = values_.data();
    id_.job = 2;
    dmumps_c(&id_);
    check("factorization (singular or unstable tangent)");
  }

  void solve(std::vector<double>& rhs) override {
    id_.rhs = rhs.data();
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    id_.job = 3;
    dmumps_c(&id_);
    check("solve");
  }

  std::string name() const override { return "mumps"; }

 private:
  void check(const char* phase) const {
    if (id_.infog[0] < 0)
      throw LinearSolverError(std::string("MUMPS ") + phase + " failed, INFOG(1) = " + std::to_string(id_.infog[0]) +
                              ", INFOG(2) = " + std::to_string(id_.infog[1]));
  }
  DMUMPS_STRUC_C id_{};
  std::vector<int> rows_, cols_;
  std::vector<double> values_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_mumps_solver() { return std::make_unique<MumpsSolver>(); }

}  // namespace strandfem
