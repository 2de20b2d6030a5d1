// Validated reads from YAML nodes: every error names the key path, the expected value and the file position.
#pragma once
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace strandfem {

// A case-file error: the message names the key and what was expected. Exit code 2 in the program.
struct CaseError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Bounds every number read from a case file obeys. In N, mm, MPa no physical input lies outside them, and
// products of a few such values (E d^4, k / L^3) stay far from overflow and underflow in double precision.
constexpr double kMaxNumberMagnitude = 1e15;
constexpr double kMinPositiveValue = 1e-12;

// The path of item i of the list at `path`: "steps[2]".
inline std::string list_item(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const YAML::Node& node, const std::string& path, const std::string& what) const;
  // Rejects keys outside `allowed` (typos must not become silent defaults).
  void check_keys(const YAML::Node& map, const std::string& path, const std::vector<const char*>& allowed) const;
  // The value of a required key of `map` (which must be a mapping).
  YAML::Node require(const YAML::Node& map, const std::string& path, const char* key) const;

  double number(const YAML::Node& node, const std::string& path) const;
  double positive(const YAML::Node& node, const std::string& path, const char* unit) const;
  double non_negative(const YAML::Node& node, const std::string& path, const char* unit) const;
  // An integer in [minimum, maximum]; read in 64 bits, so that 2^31 and beyond are refused, never wrapped.
  int integer(const YAML::Node& node, const std::string& path, int minimum, int maximum) const;
  std::string text(const YAML::Node& node, const std::string& path) const;
  bool boolean(const YAML::Node& node, const std::string& path) const;
  std::string choice(const YAML::Node& node, const std::string& path, const std::vector<std::string>& options) const;
  std::string choice(const YAML::Node& node, const std::string& path, std::initializer_list<const char*> options) const {
    return choice(node, path, std::vector<std::string>(options.begin(), options.end()));
  }
  std::vector<double> numbers(const YAML::Node& node, const std::string& path, std::size_t count) const;

 private:
  std::string file_;
};

}  // namespace strandfem
