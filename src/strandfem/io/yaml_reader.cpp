#include "strandfem/io/yaml_reader.hpp"

#include <cmath>

namespace strandfem {

void YamlReader::fail(const YAML::Node& node, const std::string& path, const std::string& what) const {
  std::string where = file_;
  if (node.IsDefined() && node.Mark().line >= 0)
    where += ":" + std::to_string(node.Mark().line + 1) + ":" + std::to_string(node.Mark().column + 1);
  throw CaseError(where + ": " + path + ": " + what);
}

void YamlReader::check_keys(const YAML::Node& map, const std::string& path,
                            const std::vector<const char*>& allowed) const {
  if (!map.IsMap()) fail(map, path, "expected a mapping of keys");
  for (const auto& entry : map) {
    const std::string key = entry.first.as<std::string>();
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      fail(entry.first, path.empty() ? key : path + "." + key, "unknown key (expected one of: " + list + ")");
    }
  }
}

YAML::Node YamlReader::require(const YAML::Node& map, const std::string& path, const char* key) const {
  if (!map.IsMap()) fail(map, path, std::string("expected a mapping with key '") + key + "'");
  const YAML::Node n = map[key];
  if (!n.IsDefined() || n.IsNull()) fail(map, path.empty() ? key : path + "." + key, "missing required key");
  return n;
}

double YamlReader::number(const YAML::Node& node, const std::string& path) const {
  if (!node.IsScalar()) fail(node, path, "expected a number");
  double v;
  if (!YAML::convert<double>::decode(node, v) || !std::isfinite(v))
    fail(node, path, "expected a finite number, got '" + node.Scalar() + "'");
  if (std::abs(v) > kMaxNumberMagnitude)
    fail(node, path, "expected a number of magnitude at most 1e15 (units N, mm, MPa), got " + node.Scalar());
  return v;
}

double YamlReader::positive(const YAML::Node& node, const std::string& path, const char* unit) const {
  const double v = number(node, path);
  if (!(v >= kMinPositiveValue))
    fail(node, path, std::string("expected a positive value of at least 1e-12 (") + unit + "), got " + node.Scalar());
  return v;
}

double YamlReader::non_negative(const YAML::Node& node, const std::string& path, const char* unit) const {
  const double v = number(node, path);
  if (v < 0) fail(node, path, std::string("expected a value >= 0 (") + unit + "), got " + node.Scalar());
  return v;
}

int YamlReader::integer(const YAML::Node& node, const std::string& path, int minimum, int maximum) const {
  const std::string range = "expected an integer in " + std::to_string(minimum) + ".." + std::to_string(maximum);
  if (!node.IsScalar()) fail(node, path, range);
  long long v;
  // Values beyond 64 bits fail to decode; those within are compared before narrowing to int.
  if (!YAML::convert<long long>::decode(node, v) || v < minimum || v > maximum)
    fail(node, path, range + ", got '" + node.Scalar() + "'");
  return static_cast<int>(v);
}

std::string YamlReader::text(const YAML::Node& node, const std::string& path) const {
  if (!node.IsScalar()) fail(node, path, "expected a string");
  return node.Scalar();
}

bool YamlReader::boolean(const YAML::Node& node, const std::string& path) const {
  bool v;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, v)) fail(node, path, "expected true or false");
  return v;
}

std::string YamlReader::choice(const YAML::Node& node, const std::string& path,
                               const std::vector<std::string>& options) const {
  const std::string v = text(node, path);
  std::string list;
  for (const std::string& o : options) {
    if (v == o) return v;
    list += (list.empty() ? "" : ", ") + o;
  }
  fail(node, path, "expected one of: " + list + "; got '" + v + "'");
}

std::vector<double> YamlReader::numbers(const YAML::Node& node, const std::string& path, std::size_t count) const {
  if (!node.IsSequence() || node.size() != count)
    fail(node, path, "expected a list of " + std::to_string(count) + " numbers");
  std::vector<double> v;
  for (std::size_t i = 0; i < count; ++i) v.push_back(number(node[i], path + "[" + std::to_string(i) + "]"));
  return v;
}

}  // namespace strandfem
