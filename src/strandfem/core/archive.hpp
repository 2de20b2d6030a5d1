// Binary archives of solution state (checkpoints): plain values, vectors and maps, written in the machine's byte
// order and read back with every length checked.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "strandfem/core/types.hpp"

namespace strandfem {

template <class T>
struct is_pair : std::false_type {};
template <class A, class B>
struct is_pair<std::pair<A, B>> : std::true_type {};

// A checkpoint that cannot be read back (truncated, corrupt, or from another model or version).
struct ArchiveError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ArchiveWriter {
 public:
  template <class A, class B>
  void value(const std::pair<A, B>& v) {
    value(v.first);
    value(v.second);
  }
  void value(const std::string& s) { string(s); }
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "archive values must be trivially copyable");
    const auto* bytes = reinterpret_cast<const char*>(&v);
    buffer_.insert(buffer_.end(), bytes, bytes + sizeof(T));
  }
  template <class T>
  void vector(const std::vector<T>& v) {
    value(static_cast<std::uint64_t>(v.size()));
    if constexpr (is_pair<T>::value) {
      for (const T& item : v) value(item);
    } else if constexpr (std::is_trivially_copyable_v<T>) {
      const auto* bytes = reinterpret_cast<const char*>(v.data());
      buffer_.insert(buffer_.end(), bytes, bytes + sizeof(T) * v.size());
    } else {
      for (const T& item : v) vector(item);  // vectors of vectors
    }
  }
  void string(const std::string& s) { vector(std::vector<char>(s.begin(), s.end())); }
  void vec3(const Vec3& v) { value(std::array<double, 3>{v.x(), v.y(), v.z()}); }
  void quaternion(const Quaternion& q) { value(std::array<double, 4>{q.w(), q.x(), q.y(), q.z()}); }
  template <class K, class V>
  void map(const std::map<K, V>& m) {
    value(static_cast<std::uint64_t>(m.size()));
    for (const auto& [key, item] : m) {
      value(key);
      value(item);
    }
  }
  // A named section: reading checks the name, so that a mismatch is reported where it happens.
  void section(const std::string& name) { string(name); }
  const std::vector<char>& bytes() const { return buffer_; }

 private:
  std::vector<char> buffer_;
};

class ArchiveReader {
 public:
  explicit ArchiveReader(std::vector<char> bytes) : buffer_(std::move(bytes)) {}
  template <class T>
  T value() {
    if constexpr (is_pair<T>::value) {
      T v;
      v.first = value<typename T::first_type>();
      v.second = value<typename T::second_type>();
      return v;
    } else if constexpr (std::is_same_v<T, std::string>) {
      return string();
    } else {
      return plain_value<T>();
    }
  }
  template <class T>
  T plain_value() {
    static_assert(std::is_trivially_copyable_v<T>, "archive values must be trivially copyable");
    T v;
    std::memcpy(&v, take(sizeof(T)), sizeof(T));
    return v;
  }
  template <class T>
  void value(T& v) { v = value<T>(); }
  template <class T>
  std::vector<T> vector() {
    const auto n = value<std::uint64_t>();
    std::vector<T> v;
    if constexpr (is_pair<T>::value) {
      if (n > buffer_.size() - position_) throw ArchiveError("checkpoint is truncated or corrupt");
      v.resize(n);
      for (T& item : v) item = value<T>();
    } else if constexpr (std::is_trivially_copyable_v<T>) {
      if (n > (buffer_.size() - position_) / std::max<std::size_t>(1, sizeof(T))) throw ArchiveError("checkpoint is truncated or corrupt");
      v.resize(n);
      if (n > 0) std::memcpy(v.data(), take(sizeof(T) * n), sizeof(T) * n);
    } else {
      if (n > buffer_.size() - position_) throw ArchiveError("checkpoint is truncated or corrupt");
      v.resize(n);
      for (T& item : v) item = vector<typename T::value_type>();
    }
    return v;
  }
  template <class T>
  void vector(std::vector<T>& v) { v = vector<T>(); }
  std::string string() {
    const std::vector<char> chars = vector<char>();
    return {chars.begin(), chars.end()};
  }
  Vec3 vec3() {
    const auto v = value<std::array<double, 3>>();
    return {v[0], v[1], v[2]};
  }
  Quaternion quaternion() {
    const auto q = value<std::array<double, 4>>();
    return Quaternion(q[0], q[1], q[2], q[3]);
  }
  template <class K, class V>
  void map(std::map<K, V>& m) {
    m.clear();
    const auto n = value<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i) {
      const K key = value<K>();
      m[key] = value<V>();
    }
  }
  void section(const std::string& name) {
    if (string() != name) throw ArchiveError("checkpoint section '" + name + "' is missing or out of place");
  }
  // Throws unless `actual` equals what the archive holds: e.g. a node count that must match the model.
  template <class T>
  void expect(const T& actual, const std::string& what) {
    if (value<T>() != actual) throw ArchiveError("checkpoint does not match this model: " + what + " differs");
  }
  bool at_end() const { return position_ == buffer_.size(); }

 private:
  const char* take(std::size_t n) {
    if (n > buffer_.size() - position_) throw ArchiveError("checkpoint is truncated or corrupt");
    const char* p = buffer_.data() + position_;
    position_ += n;
    return p;
  }
  std::vector<char> buffer_;
  std::size_t position_ = 0;
};

}  // namespace strandfem
