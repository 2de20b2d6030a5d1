#include "strandfem/solver/linear_solver.hpp"

#include <algorithm>
#include <stdexcept>

namespace strandfem {

std::unique_ptr<LinearSolver> make_umfpack_solver();
std::unique_ptr<LinearSolver> make_mumps_solver();

int SparsePattern::find(int row, int col) const {
  const auto begin = row_index.begin() + column_start[col], end = row_index.begin() + column_start[col + 1];
  const auto it = std::lower_bound(begin, end, row);
  return (it != end && *it == row) ? static_cast<int>(it - row_index.begin()) : -1;
}

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name) {
  if (name == "mumps") return make_mumps_solver();
  if (name == "umfpack") return make_umfpack_solver();
  throw std::invalid_argument("unknown linear solver '" + name + "' (expected mumps or umfpack)");
}

}  // namespace strandfem
