#include "strandfem/solver/linear_solver.hpp"

#include <metis.h>

#include <algorithm>
#include <functional>
#include <iterator>
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
  std::vector<int> block_start = pattern.block_start;
  if (block_start.empty()) {
    block_start.resize(n + 1);
    std::iota(block_start.begin(), block_start.end(), 0);
  }
  if (block_start.front() != 0 || block_start.back() != n ||
      std::adjacent_find(block_start.begin(), block_start.end(), std::greater_equal<int>()) != block_start.end())
    throw std::invalid_argument("sparse pattern: block starts must rise strictly from 0 to the matrix size");
  const int blocks = static_cast<int>(block_start.size()) - 1;
  std::vector<int> block_of(n);
  for (int b = 0; b < blocks; ++b) std::fill(block_of.begin() + block_start[b], block_of.begin() + block_start[b + 1], b);
  // Adjacency of A + A^T between blocks, without self-loops: METIS wants an undirected graph. Each block's first
  // column stands for all of its columns (and, through the symmetrization, its rows). Rows are sorted in each
  // column and blocks are runs of consecutive equations, so a column's blocks come sorted; the transpose comes
  // sorted from a counting pass, and the union of the two sorted lists needs no sort (linear in the entries).
  std::vector<int> column_start(blocks + 1, 0), column_blocks;
  for (int b = 0; b < blocks; ++b) {
    const int col = block_start[b];
    int last = -1;
    for (int k = pattern.column_start[col]; k < pattern.column_start[col + 1]; ++k) {
      const int other = block_of[pattern.row_index[k]];
      if (other != b && other != last) column_blocks.push_back(other);
      last = other;
    }
    column_start[b + 1] = static_cast<int>(column_blocks.size());
  }
  std::vector<int> row_start(blocks + 1, 0), row_blocks(column_blocks.size());
  for (int other : column_blocks) ++row_start[other + 1];
  std::partial_sum(row_start.begin(), row_start.end(), row_start.begin());
  {
    std::vector<int> next(row_start.begin(), row_start.end() - 1);
    for (int b = 0; b < blocks; ++b)
      for (int k = column_start[b]; k < column_start[b + 1]; ++k) row_blocks[next[column_blocks[k]]++] = b;
  }
  std::vector<idx_t> adjacency_start(blocks + 1, 0), adjacency, weight(blocks);
  adjacency.reserve(2 * column_blocks.size());
  for (int b = 0; b < blocks; ++b) {
    std::set_union(column_blocks.begin() + column_start[b], column_blocks.begin() + column_start[b + 1],
                   row_blocks.begin() + row_start[b], row_blocks.begin() + row_start[b + 1], std::back_inserter(adjacency));
    adjacency_start[b + 1] = static_cast<idx_t>(adjacency.size());
    weight[b] = block_start[b + 1] - block_start[b];
  }
  std::vector<int> position(n);
  std::iota(position.begin(), position.end(), 0);
  if (adjacency.empty()) return position;  // block-diagonal matrix: nothing to order, and METIS rejects empty graphs
  idx_t vertices = blocks;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  // METIS' perm is the pivot order (perm[k] = block eliminated k-th); its iperm is not needed.
  std::vector<idx_t> pivot_order(blocks), block_position(blocks);
  const int status = METIS_NodeND(&vertices, adjacency_start.data(), adjacency.data(), weight.data(), options,
                                  pivot_order.data(), block_position.data());
  if (status != METIS_OK) throw LinearSolverError("METIS_NodeND failed, status " + std::to_string(status));
  int next = 0;
  for (int k = 0; k < blocks; ++k) {
    const int b = pivot_order[k];
    for (int i = block_start[b]; i < block_start[b + 1]; ++i) position[i] = next++;
  }
  return position;
}

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name) {
  if (name == "mumps") return make_mumps_solver();
  if (name == "mumps_single") return make_single_precision_mumps_solver();
  if (name == "umfpack") return make_umfpack_solver();
  throw std::invalid_argument("unknown linear solver '" + name + "' (expected mumps, mumps_single or umfpack)");
}

}  // namespace strandfem
