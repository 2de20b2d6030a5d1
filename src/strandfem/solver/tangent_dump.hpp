// A tangent matrix written to a file as it was factored, so that benchmarks can time solvers on real tangents.
#pragma once
#include <filesystem>
#include <vector>

#include "strandfem/solver/linear_solver.hpp"

namespace strandfem {

struct StoredTangent {
  SparsePattern pattern;
  std::vector<double> values;
};

// Binary file: a magic word and format version, then the pattern (CSC and node blocks) and the values.
void write_tangent(const std::filesystem::path& path, const SparsePattern& pattern, const std::vector<double>& values);
// Throws std::runtime_error naming the file when it is not a tangent of this format or is cut short.
StoredTangent read_tangent(const std::filesystem::path& path);

}  // namespace strandfem
