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

class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const YAML::Node& node, const std::string& path, const std::string& what) const;
  // Rejects keys outside `allowed` (typos must not become silent defaults).
  void check_keys(const YAML::Node& map, const std::string& path, std::initializer_list<const char*> allowed) const;
  YAML::Node require(const YAML::Node& map, const std::string& path, const char* key) const;

  double number(const YAML::Node& node, const std::string& path) const;
  double positive(const YAML::Node& node, const std::string& path, const char* unit) const;
  double non_negative(const YAML::Node& node, const std::string& path, const char* unit) const;
  int integer(const YAML::Node& node, const std::string& path, int minimum) const;
  std::string text(const YAML::Node& node, const std::string& path) const;
  bool boolean(const YAML::Node& node, const std::string& path) const;
  std::string choice(const YAML::Node& node, const std::string& path, std::initializer_list<const char*> options) const;
  std::vector<double> numbers(const YAML::Node& node, const std::string& path, std::size_t count) const;

 private:
  std::string file_;
};

}  // namespace strandfem
