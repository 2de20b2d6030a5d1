// The tangent file of `--dump-tangent`: written and read back bit for bit, and a file that is not one refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "strandfem/solver/tangent_dump.hpp"

namespace strandfem {
namespace {

TEST(TangentDump, RoundTripsPatternBlocksAndValues) {
  SparsePattern p;
  p.size = 3;
  p.column_start = {0, 2, 3, 5};
  p.row_index = {0, 2, 1, 0, 2};
  p.block_start = {0, 1, 3};
  const std::vector<double> values = {4.0, -1.5, 1e-300, 0.1, -7.25};
  const auto path = std::filesystem::temp_directory_path() / "strandfem_tangent_dump_test.bin";
  write_tangent(path, p, values);
  const StoredTangent back = read_tangent(path);
  EXPECT_EQ(back.pattern.size, 3);
  EXPECT_EQ(back.pattern.column_start, p.column_start);
  EXPECT_EQ(back.pattern.row_index, p.row_index);
  EXPECT_EQ(back.pattern.block_start, p.block_start);
  EXPECT_EQ(back.values, values);
  // A row index beyond the matrix: refused before it addresses anything.
  SparsePattern bad = p;
  bad.row_index[1] = 3;
  write_tangent(path, bad, values);
  EXPECT_THROW(read_tangent(path), std::runtime_error);
  write_tangent(path, p, values);
  // Cut short: refused with the file's name.
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 8);
  try {
    read_tangent(path);
    FAIL() << "a cut file was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  // Not a tangent file at all.
  std::ofstream(path) << "step,increment\n";
  EXPECT_THROW(read_tangent(path), std::runtime_error);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace strandfem
