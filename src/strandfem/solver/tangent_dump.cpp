#include "strandfem/solver/tangent_dump.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>

namespace strandfem {
namespace {

constexpr char kMagic[8] = {'S', 'F', 'T', 'A', 'N', 'G', 'T', '1'};

template <class T>
void put(std::ofstream& out, const std::vector<T>& v) {
  const std::int64_t count = static_cast<std::int64_t>(v.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(sizeof(T) * v.size()));
}

template <class T>
std::vector<T> take(std::ifstream& in, const std::filesystem::path& path, std::int64_t limit) {
  std::int64_t count = -1;
  in.read(reinterpret_cast<char*>(&count), sizeof count);
  if (!in || count < 0 || count > limit) throw std::runtime_error("tangent file " + path.string() + ": bad array length");
  std::vector<T> v(static_cast<std::size_t>(count));
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(sizeof(T) * v.size()));
  if (!in) throw std::runtime_error("tangent file " + path.string() + ": cut short");
  return v;
}

}  // namespace

void write_tangent(const std::filesystem::path& path, const SparsePattern& pattern, const std::vector<double>& values) {
  std::ofstream out(path, std::ios::binary);
  out.write(kMagic, sizeof kMagic);
  const std::int32_t size = pattern.size;
  out.write(reinterpret_cast<const char*>(&size), sizeof size);
  put(out, pattern.column_start);
  put(out, pattern.row_index);
  put(out, pattern.block_start);
  put(out, values);
  if (!out) throw std::runtime_error("could not write tangent file " + path.string());
}

StoredTangent read_tangent(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open tangent file " + path.string());
  char magic[sizeof kMagic] = {};
  in.read(magic, sizeof magic);
  if (!in || std::string(magic, sizeof magic) != std::string(kMagic, sizeof kMagic))
    throw std::runtime_error("not a StrandFEM tangent file (format 1): " + path.string());
  StoredTangent t;
  std::int32_t size = -1;
  in.read(reinterpret_cast<char*>(&size), sizeof size);
  if (!in || size < 0) throw std::runtime_error("tangent file " + path.string() + ": bad size");
  t.pattern.size = size;
  const std::int64_t limit = std::int64_t(1) << 40;
  t.pattern.column_start = take<int>(in, path, std::int64_t(size) + 1);
  t.pattern.row_index = take<int>(in, path, limit);
  t.pattern.block_start = take<int>(in, path, std::int64_t(size) + 1);
  t.values = take<double>(in, path, limit);
  if (t.pattern.column_start.size() != static_cast<std::size_t>(size) + 1 ||
      t.pattern.column_start.back() != static_cast<int>(t.pattern.row_index.size()) ||
      t.values.size() != t.pattern.row_index.size())
    throw std::runtime_error("tangent file " + path.string() + ": pattern and values do not agree");
  // Indices are checked before anyone uses them to address the values.
  const auto& start = t.pattern.column_start;
  bool valid = start.front() == 0 && std::is_sorted(start.begin(), start.end());
  for (int row : t.pattern.row_index) valid = valid && row >= 0 && row < size;
  if (!valid) throw std::runtime_error("tangent file " + path.string() + ": column starts or row indices out of range");
  return t;
}

}  // namespace strandfem
