#include "strandfem/solver/linear_solver.hpp"

#include <metis.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace strandfem {

std::unique_ptr<LinearSolver> make_umfpack_solver();
std::unique_ptr<LinearSolver> make_mumps_solver();
std::unique_ptr<LinearSolver> make_single_precision_mumps_solver();

int SparsePattern::find(int row, int col) const {
  const auto begin = row_index.begin() + column_start[col], end = row_index.begin() + column_start[col + 1];
  const auto it = std::lower_bound(begin, end, row);
  return (it != end && *it == row) ? static_cast<int>(it - row_index.begin()) : -1;
}

std::vector<int> nested_dissection_ordering(const SparsePattern& pattern) {
  static_assert(sizeof(idx_t) == sizeof(int), "libmetis is expected with 32-bit indices (Debian's IDXTYPEWIDTH 32)");
  const int n = pattern.size;
  // Adjacency of A + A^T without the diagonal: METIS wants an undirected graph without self-loops.
  std::vector<std::vector<int>> neighbours(n);
  for (int col = 0; col < n; ++col)
    for (int k = pattern.column_start[col]; k < pattern.column_start[col + 1]; ++k) {
      const int row = pattern.row_index[k];
      if (row == col) continue;
      neighbours[row].push_back(col);
      neighbours[col].push_back(row);
    }
  std::vector<idx_t> adjacency_start(n + 1, 0), adjacency;
  for (int i = 0; i < n; ++i) {
    std::sort(neighbours[i].begin(), neighbours[i].end());
    neighbours[i].erase(std::unique(neighbours[i].begin(), neighbours[i].end()), neighbours[i].end());
    adjacency.insert(adjacency.end(), neighbours[i].begin(), neighbours[i].end());
    adjacency_start[i + 1] = static_cast<idx_t>(adjacency.size());
  }
  std::vector<int> position(n);
  std::iota(position.begin(), position.end(), 0);
  if (adjacency.empty()) return position;  // diagonal matrix: nothing to order, and METIS rejects empty graphs
  idx_t vertices = n;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  // METIS' perm is the pivot order (perm[k] = variable eliminated k-th); its iperm is the position of each variable.
  std::vector<idx_t> pivot_order(n);
  const int status = METIS_NodeND(&vertices, adjacency_start.data(), adjacency.data(), nullptr, options,
                                  pivot_order.data(), position.data());
  if (status != METIS_OK) throw LinearSolverError("METIS_NodeND failed, status " + std::to_string(status));
  return position;
}

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name) {
  if (name == "mumps") return make_mumps_solver();
  if (name == "mumps_single") return make_single_precision_mumps_solver();
  if (name == "umfpack") return make_umfpack_solver();
  throw std::invalid_argument("unknown linear solver '" + name + "' (expected mumps, mumps_single or umfpack)");
}

}  // namespace strandfem
