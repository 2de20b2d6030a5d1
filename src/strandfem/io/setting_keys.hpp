// A key of a settings mapping declared once: its name, type and range, unit, meaning and how it is read; the one
// table that drives the reader, the default, summary.json's resolved configuration and docs/case-files.md.
#pragma once
#include <functional>
#include <limits>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "strandfem/core/types.hpp"
#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {

// The values a number key accepts: an interval whose ends are open or closed ("> 0" is (0, inf) with the reader's
// smallest positive value).
struct NumberRange {
  double lower = -kMaxNumberMagnitude;
  double upper = kMaxNumberMagnitude;
  bool lower_open = false;
  bool upper_open = false;

  static NumberRange positive() { return {0.0, kMaxNumberMagnitude, true, false}; }
  static NumberRange non_negative() { return {0.0, kMaxNumberMagnitude, false, false}; }
  static NumberRange closed(double lower, double upper) { return {lower, upper, false, false}; }
  static NumberRange open(double lower, double upper) { return {lower, upper, true, true}; }
  static NumberRange half_open(double lower, double upper) { return {lower, upper, false, true}; }  // [lower, upper)
  static NumberRange below(double upper) { return {0.0, upper, true, true}; }                       // (0, upper)
  static NumberRange any() { return {}; }

  bool unbounded() const { return lower <= -kMaxNumberMagnitude && upper >= kMaxNumberMagnitude; }

  bool contains(double value) const;
  std::string text() const;  // "> 0", "≥ 0", "in [0, 1)"
};

constexpr double kRadiansPerDegree = 0.017453292519943295;  // pi / 180

// A number's type as the page writes it: its unit, then its range ("mm, > 0", "deg in (0, 90)", "N").
std::string number_type_text(const NumberRange& range, const std::string& unit);

// How the page writes a number (12 significant digits, exponents without leading zeros: 1e-8, 0.0005, 25).
std::string number_text(double value);

// Which part of docs/case-files.md lists a key: the physics tables or "Advanced: numerical keys".
enum class KeySection { kPhysics, kAdvanced };

template <class Settings>
struct SettingKey {
  std::string name;
  std::string type;           // type, unit and range as the page writes them
  std::string meaning;        // one line
  std::string when_to_touch;  // advanced keys: when a user should change it
  KeySection section = KeySection::kAdvanced;
  std::function<void(const YamlReader&, const YAML::Node&, const std::string& path, Settings&)> read;
  std::function<nlohmann::json(const Settings&)> value;  // the setting as the run uses it
  std::string default_rule;   // the default where it is a rule in words, not a value (else empty)
  bool required = false;      // no default: the mapping must give it

  SettingKey& in_section(KeySection where) { section = where; return *this; }
  SettingKey& must_be_given() { required = true; return *this; }
  SettingKey& default_is(std::string rule) { default_rule = std::move(rule); return *this; }
  SettingKey& typed(std::string text) { type = std::move(text); return *this; }
};

// A key with its description; `read` and `value` still to be set.
template <class Settings>
SettingKey<Settings> described_key(std::string name, std::string type, std::string meaning, std::string when_to_touch) {
  SettingKey<Settings> key;
  key.name = std::move(name);
  key.type = std::move(type);
  key.meaning = std::move(meaning);
  key.when_to_touch = std::move(when_to_touch);
  return key;
}

template <class Settings>
SettingKey<Settings> number_key(std::string name, double Settings::*member, NumberRange range, const std::string& unit,
                                std::string meaning, std::string when_to_touch = {}) {
  auto key = described_key<Settings>(std::move(name), number_type_text(range, unit), std::move(meaning), std::move(when_to_touch));
  key.read = [member, range, unit](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) {
    const char* shown_unit = unit.empty() ? "-" : unit.c_str();
    const double v = range.lower != 0 ? reader.number(node, path)
                     : range.lower_open ? reader.positive(node, path, shown_unit)
                                        : reader.non_negative(node, path, shown_unit);
    if (!range.contains(v)) reader.fail(node, path, "expected a value " + range.text() + ", got " + node.Scalar());
    s.*member = v;
  };
  key.value = [member](const Settings& s) { return nlohmann::json(s.*member); };
  return key;
}

// An angle the page and the case give in degrees and the settings hold in radians.
template <class Settings>
SettingKey<Settings> degree_key(std::string name, double Settings::*member, NumberRange range_in_degrees, std::string meaning,
                                std::string when_to_touch = {}) {
  auto key = described_key<Settings>(std::move(name), number_type_text(range_in_degrees, "deg"), std::move(meaning), std::move(when_to_touch));
  key.read = [member, range_in_degrees](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) {
    const double degrees = reader.number(node, path);
    if (!range_in_degrees.contains(degrees))
      reader.fail(node, path, "expected an angle " + range_in_degrees.text() + " degrees, got " + node.Scalar());
    s.*member = degrees * kRadiansPerDegree;
  };
  key.value = [member](const Settings& s) { return nlohmann::json(s.*member / kRadiansPerDegree); };
  return key;
}

// A number a mapping may leave out (null in the resolved configuration), read in `unit` and held times `scale`
// (degrees held in radians: kRadiansPerDegree).
template <class Settings>
SettingKey<Settings> optional_number_key(std::string name, std::optional<double> Settings::*member, NumberRange range, const std::string& unit,
                                         std::string meaning, double scale = 1.0) {
  auto key = described_key<Settings>(std::move(name), number_type_text(range, unit), std::move(meaning), "");
  key.read = [member, range, scale](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) {
    const double v = reader.number(node, path);
    if (!range.contains(v)) reader.fail(node, path, "expected a value " + range.text() + ", got " + node.Scalar());
    s.*member = v * scale;
  };
  key.value = [member, scale](const Settings& s) { return s.*member ? nlohmann::json(*(s.*member) / scale) : nlohmann::json(nullptr); };
  key.default_rule = "—";
  return key;
}

template <class Settings>
SettingKey<Settings> integer_key(std::string name, int Settings::*member, int minimum, int maximum, std::string meaning,
                                 std::string when_to_touch = {}) {
  const std::string range = maximum == std::numeric_limits<int>::max() ? "integer ≥ " + std::to_string(minimum)
                                                                       : "integer " + std::to_string(minimum) + ".." + std::to_string(maximum);
  auto key = described_key<Settings>(std::move(name), range, std::move(meaning), std::move(when_to_touch));
  key.read = [member, minimum, maximum](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) {
    s.*member = reader.integer(node, path, minimum, maximum);
  };
  key.value = [member](const Settings& s) { return nlohmann::json(s.*member); };
  return key;
}

template <class Settings>
SettingKey<Settings> boolean_key(std::string name, bool Settings::*member, std::string meaning, std::string when_to_touch = {}) {
  auto key = described_key<Settings>(std::move(name), "bool", std::move(meaning), std::move(when_to_touch));
  key.read = [member](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) {
    s.*member = reader.boolean(node, path);
  };
  key.value = [member](const Settings& s) { return nlohmann::json(s.*member); };
  return key;
}

template <class Settings>
SettingKey<Settings> text_key(std::string name, std::string Settings::*member, std::string type, std::string meaning) {
  auto key = described_key<Settings>(std::move(name), std::move(type), std::move(meaning), "");
  key.read = [member](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) { s.*member = reader.text(node, path); };
  key.value = [member](const Settings& s) { return (s.*member).empty() ? nlohmann::json(nullptr) : nlohmann::json(s.*member); };
  return key;
}

// Three numbers `[x, y, z]`, held as a Vec3 (or an optional one, null in the resolved configuration when left out).
template <class Settings, class Vector>
SettingKey<Settings> vector_key(std::string name, Vector Settings::*member, std::string type, std::string meaning) {
  auto key = described_key<Settings>(std::move(name), std::move(type), std::move(meaning), "");
  key.read = [member](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) {
    const auto v = reader.numbers(node, path, 3);
    s.*member = Vec3(v[0], v[1], v[2]);
  };
  key.value = [member](const Settings& s) {
    const auto to_json = [](const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
    if constexpr (std::is_same_v<Vector, Vec3>) return to_json(s.*member);
    else return s.*member ? to_json(*(s.*member)) : nlohmann::json(nullptr);
  };
  return key;
}

template <class Settings>
SettingKey<Settings> optional_integer_key(std::string name, std::optional<int> Settings::*member, int minimum, int maximum, std::string meaning) {
  auto key = described_key<Settings>(std::move(name), "integer " + std::to_string(minimum) + ".." + std::to_string(maximum), std::move(meaning), "");
  key.read = [member, minimum, maximum](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) {
    s.*member = reader.integer(node, path, minimum, maximum);
  };
  key.value = [member](const Settings& s) { return s.*member ? nlohmann::json(*(s.*member)) : nlohmann::json(nullptr); };
  key.default_rule = "—";
  return key;
}

// A mapping read later by code of its own (a node selector): the key keeps the YAML node.
template <class Settings>
SettingKey<Settings> node_key(std::string name, YAML::Node Settings::*member, std::string type, std::string meaning) {
  auto key = described_key<Settings>(std::move(name), std::move(type), std::move(meaning), "");
  key.read = [member](const YamlReader&, const YAML::Node& node, const std::string&, Settings& s) { s.*member = node; };
  key.value = [](const Settings&) { return nlohmann::json(nullptr); };
  return key;
}

// A key whose value is one of named options, each stored as a value of the member's type (an enum or a string).
template <class Settings, class Value>
SettingKey<Settings> choice_key(std::string name, Value Settings::*member, std::vector<std::pair<std::string, Value>> options,
                                std::string meaning, std::string when_to_touch = {}) {
  std::string type;
  for (const auto& option : options) type += (type.empty() ? "`" : " \\| `") + option.first + "`";
  auto key = described_key<Settings>(std::move(name), type, std::move(meaning), std::move(when_to_touch));
  key.read = [member, options](const YamlReader& reader, const YAML::Node& node, const std::string& path, Settings& s) {
    std::vector<std::string> names;
    for (const auto& option : options) names.push_back(option.first);
    const std::string chosen = reader.choice(node, path, names);
    for (const auto& option : options)
      if (option.first == chosen) s.*member = option.second;
  };
  key.value = [member, options](const Settings& s) {
    for (const auto& option : options)
      if (option.second == s.*member) return nlohmann::json(option.first);
    return nlohmann::json(nullptr);
  };
  return key;
}

// The keys of a table that all belong to one section of the page.
template <class Settings>
std::vector<SettingKey<Settings>> keys_in_section(KeySection section, std::vector<SettingKey<Settings>> table) {
  for (auto& key : table) key.section = section;
  return table;
}

// The table's key names, for YamlReader::check_keys (with `extra` keys a mapping reads by code of its own).
template <class Settings>
std::vector<const char*> key_names(const std::vector<SettingKey<Settings>>& table, std::vector<const char*> extra = {}) {
  std::vector<const char*> names;
  for (const auto& key : table) names.push_back(key.name.c_str());
  names.insert(names.end(), extra.begin(), extra.end());
  return names;
}

// Reads every key of `table` that `node` holds into `settings`, over its defaults; `mapping`: the path's prefix.
template <class Settings>
void read_setting_keys(const YamlReader& reader, const YAML::Node& node, const std::string& mapping,
                       const std::vector<SettingKey<Settings>>& table, Settings& settings) {
  for (const auto& key : table) {
    if (const YAML::Node n = node[key.name])
      key.read(reader, n, mapping.empty() ? key.name : mapping + "." + key.name, settings);
    else if (key.required)
      reader.require(node, mapping, key.name.c_str());
  }
}

// Every key of `table` with the value `settings` holds (summary.json's resolved configuration).
template <class Settings>
nlohmann::json resolved_setting_keys(const std::vector<SettingKey<Settings>>& table, const Settings& settings) {
  nlohmann::json resolved = nlohmann::json::object();
  for (const auto& key : table) resolved[key.name] = key.value(settings);
  return resolved;
}

// The key's row of docs/case-files.md: key, type, default, meaning, and for advanced keys when to touch it.
std::string format_key_row(const std::string& path, const std::string& type, const std::string& default_text,
                           const std::string& meaning, KeySection section, const std::string& when_to_touch);
// A default as the page writes it: numbers by number_text, true/false, strings bare.
std::string default_text(const nlohmann::json& value);

template <class Settings>
std::string key_row(const std::string& mapping, const SettingKey<Settings>& key) {
  const std::string shown = key.required ? "—" : key.default_rule.empty() ? default_text(key.value(Settings{})) : key.default_rule;
  return format_key_row(mapping.empty() ? key.name : mapping + "." + key.name, key.type, shown, key.meaning, key.section, key.when_to_touch);
}

}  // namespace strandfem
