// Sparse direct solvers for unsymmetric systems behind one small interface (UMFPACK, MUMPS).
#pragma once
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace strandfem {

// Square sparse matrix pattern in compressed sparse column form (0-based, rows sorted in each column).
struct SparsePattern {
  int size = 0;
  std::vector<int> column_start;  // size + 1 entries
  std::vector<int> row_index;
  // Optional: where runs of consecutive equations that share their rows and columns begin (a node's free DOFs),
  // strictly rising, with `size` last; empty when every equation stands alone. Orderings then work on the graph
  // of the runs.
  std::vector<int> block_start;
  std::size_t nonzeros() const { return row_index.size(); }
  // Position of (row, col) in the value array, or -1 when outside the pattern.
  int find(int row, int col) const;
};

// What a solver did so far: the ordering that actually ran, the size and cost of its factors, time per phase.
struct LinearSolverStatistics {
  std::string ordering;             // read back from the solver after analysis, not the one requested
  long long factor_entries = 0;     // entries of L and U after the last factorization
  double factorization_flops = 0;   // floating-point operations of the last factorization
  int analyses = 0;
  int factorizations = 0;
  int solves = 0;
  double analysis_seconds = 0;      // wall-clock totals over all calls (steady clock)
  double factorization_seconds = 0;
  double solve_seconds = 0;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Symbolic analysis (fill-reducing ordering); kept while the pattern does not change.
  virtual void analyze(const SparsePattern& pattern) = 0;
  // Numerical factorization of values laid out as the analyzed pattern.
  virtual void factorize(const std::vector<double>& values) = 0;
  // Solves A x = b in place (b in, x out).
  virtual void solve(std::vector<double>& rhs) = 0;
  virtual std::string name() const = 0;
  virtual const LinearSolverStatistics& statistics() const = 0;
  // True when the factors are too inexact for a Newton correction (single precision): every solve is then a
  // GMRES solve of the double-precision tangent that the factors precondition.
  virtual bool needs_refinement() const { return false; }
};

// METIS nested-dissection ordering of the symmetrized pattern A + A^T (diagonal ignored): the returned
// position[i] is the 0-based place of variable i in the pivot order. Unsymmetric tangents keep a
// structurally near-symmetric pattern, so ordering A + A^T is what the multifrontal solvers want. With
// block_start, METIS orders the graph of the blocks (each weighted by its size; its first column stands for it)
// and a block's equations follow each other in the order.
std::vector<int> nested_dissection_ordering(const SparsePattern& pattern);

// "mumps_single" (single-precision factors; the case default), "mumps" or "umfpack"; throws std::invalid_argument
// for any other name.
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name);

// Thrown when a factorization fails (singular matrix, out of memory).
struct LinearSolverError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace strandfem
