// MUMPS 5.5 unsymmetric multifrontal LU, ordered by METIS through libmetis, in double precision or in single
// precision (factors that precondition GMRES on the double-precision tangent); on one process or, with the MPI build
// under mpirun, on all of them (mumps_processes.hpp).
#include <chrono>
#include <string>
#include <type_traits>

#include "strandfem/solver/linear_solver.hpp"
#include "strandfem/solver/mumps_call.hpp"

namespace strandfem {
namespace {

constexpr int kUserOrdering = 1;        // ICNTL(7) = 1: pivot order given in PERM_IN

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Name of the ordering MUMPS reports in INFOG(7) after analysis.
std::string ordering_name(int infog7) {
  switch (infog7) {
    case 0: return "amd";
    case 1: return "metis (user-supplied via libmetis)";  // the only pivot order this class supplies
    case 2: return "amf";
    case 3: return "scotch";
    case 4: return "pord";
    case 5: return "metis";
    case 6: return "qamd";
    default: return "unknown (INFOG(7) = " + std::to_string(infog7) + ")";
  }
}

// MUMPS stores counts that overflow a 4-byte INFOG entry as negative millions.
long long unpack_count(int value) { return value < 0 ? -1'000'000LL * value : value; }

struct DoublePrecision {
  using Struct = DMUMPS_STRUC_C;
  using Real = double;
  static constexpr const char* name = "mumps";
};

struct SinglePrecision {
  using Struct = SMUMPS_STRUC_C;
  using Real = float;
  static constexpr const char* name = "mumps_single";
};

template <class Precision>
class MumpsSolver final : public LinearSolver {
  using Real = typename Precision::Real;
  static constexpr bool kSingle = std::is_same_v<Real, float>;

 public:
  MumpsSolver() {
    id_.comm_fortran = mumps_communicator();
    id_.par = 1;
    id_.sym = 0;  // unsymmetric: friction makes the tangent unsymmetric
    id_.job = -1;
    mumps_call(id_);
    check("initialization");
    id_.icntl[0] = -1;  // no error messages on stdout: errors are reported through exceptions
    id_.icntl[1] = -1;
    id_.icntl[2] = -1;
    id_.icntl[3] = 0;
    // Debian's libmumps-seq is built without METIS (ICNTL(7) = 5 silently ran AMF or SCOTCH instead,
    // INFOG(7) = 2 or 3), and its MPI build links neither METIS nor SCOTCH. So the METIS nested dissection is
    // computed here and handed over as the pivot order, the same on either build.
    id_.icntl[6] = kUserOrdering;
    id_.icntl[13] = 50;  // ICNTL(14): 50 % working-space relaxation
    // Single-precision factors only precondition GMRES: the diagonal scaling (ICNTL(8) = 1) serves them as well
    // as the iterative row and column scaling MUMPS picks by default (7), which costs about 8 % of each
    // factorization on an S32 bending tangent and runs on one thread (docs/performance/linear-algebra.md).
    if (kSingle) id_.icntl[7] = 1;
  }
  ~MumpsSolver() override {
    id_.job = -2;
    mumps_call(id_);
  }

  void analyze(const SparsePattern& pattern) override {
    const auto start = Clock::now();
    const std::size_t entries = pattern.row_index.size();
    rows_.resize(entries);
    cols_.resize(entries);
#pragma omp parallel for schedule(static)
    for (int c = 0; c < pattern.size; ++c)
      for (int k = pattern.column_start[c]; k < pattern.column_start[c + 1]; ++k) {
        rows_[k] = pattern.row_index[k] + 1;
        cols_[k] = c + 1;
      }
    values_.assign(entries, 0.0);
    pivot_position_ = nested_dissection_ordering(pattern);
    for (int& p : pivot_position_) ++p;  // PERM_IN is 1-based
    // The pattern's node blocks (columns with the same rows) let MUMPS analyze the graph of blocks instead of
    // the graph of equations (ICNTL(15) = 1): the same pivot order and factors, in 0.12 s instead of 0.20 s on
    // an S32 bending tangent (docs/performance/linear-algebra.md).
    block_pointer_.assign(pattern.block_start.begin(), pattern.block_start.end());
    for (int& b : block_pointer_) ++b;  // BLKPTR is 1-based
    id_.icntl[14] = block_pointer_.size() > 1 ? 1 : 0;
    id_.nblk = block_pointer_.size() > 1 ? static_cast<int>(block_pointer_.size()) - 1 : 0;
    id_.blkptr = block_pointer_.size() > 1 ? block_pointer_.data() : nullptr;
    id_.blkvar = nullptr;  // blocks of consecutive equations
    id_.n = pattern.size;
    id_.nnz = static_cast<MUMPS_INT8>(rows_.size());
    id_.irn = rows_.data();
    id_.jcn = cols_.data();
    id_.a = values_.data();
    id_.perm_in = pivot_position_.data();
    id_.job = 1;
    mumps_call(id_);
    check("analysis");
    statistics_.ordering = ordering_name(id_.infog[6]);
    ++statistics_.analyses;
    statistics_.analysis_seconds += seconds_since(start);
  }

  void factorize(const std::vector<double>& values) override {
    const auto start = Clock::now();
    values_.assign(values.begin(), values.end());
    id_.a = values_.data();
    id_.job = 2;
    mumps_call(id_);
    check("factorization (singular or unstable tangent)");
    statistics_.factor_entries = unpack_count(id_.infog[28]);  // INFOG(29): entries in the factors
    statistics_.factorization_flops = id_.rinfog[2];             // RINFOG(3): flops of the elimination
    ++statistics_.factorizations;
    statistics_.factorization_seconds += seconds_since(start);
  }

  void solve(std::vector<double>& rhs) override {
    const auto start = Clock::now();
    if constexpr (kSingle) {
      rhs_.assign(rhs.begin(), rhs.end());
      id_.rhs = rhs_.data();
    } else {
      id_.rhs = rhs.data();
    }
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    id_.job = 3;
    mumps_call(id_);
    check("solve");
    if constexpr (kSingle) rhs.assign(rhs_.begin(), rhs_.end());
    ++statistics_.solves;
    statistics_.solve_seconds += seconds_since(start);
  }

  std::string name() const override { return Precision::name; }
  bool needs_refinement() const override { return kSingle; }
  const LinearSolverStatistics& statistics() const override { return statistics_; }

 private:
  void check(const char* phase) const {
    if (id_.infog[0] < 0)
      throw LinearSolverError(std::string("MUMPS ") + phase + " failed, INFOG(1) = " + std::to_string(id_.infog[0]) +
                              ", INFOG(2) = " + std::to_string(id_.infog[1]));
  }
  typename Precision::Struct id_{};
  std::vector<int> rows_, cols_;
  std::vector<int> pivot_position_;  // PERM_IN: 1-based position of each variable in the pivot order
  std::vector<int> block_pointer_;   // BLKPTR: 1-based first equation of each node block, and one past the last
  std::vector<Real> values_, rhs_;
  LinearSolverStatistics statistics_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_mumps_solver() { return std::make_unique<MumpsSolver<DoublePrecision>>(); }
std::unique_ptr<LinearSolver> make_single_precision_mumps_solver() {
  return std::make_unique<MumpsSolver<SinglePrecision>>();
}

}  // namespace strandfem
