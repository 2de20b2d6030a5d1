#include "strandfem/io/setting_keys.hpp"

#include <cstdio>
#include <regex>

namespace strandfem {

bool NumberRange::contains(double value) const {
  return (lower_open ? value > lower : value >= lower) && (upper_open ? value < upper : value <= upper);
}

std::string NumberRange::text() const {
  const bool unbounded_above = upper >= kMaxNumberMagnitude;
  if (unbounded_above && lower == 0) return lower_open ? "> 0" : "≥ 0";
  if (unbounded_above) return (lower_open ? "> " : "≥ ") + number_text(lower);
  return std::string("in ") + (lower_open ? "(" : "[") + number_text(lower) + ", " + number_text(upper) + (upper_open ? ")" : "]");
}

std::string number_type_text(const NumberRange& range, const std::string& unit) {
  if (range.unbounded()) return unit.empty() ? "number" : unit;
  const std::string text = range.text();
  if (unit.empty()) return text;
  return unit + (text.rfind("in ", 0) == 0 ? " " : ", ") + text;
}

std::string number_text(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.12g", value);
  return std::regex_replace(std::string(buffer), std::regex("e\\+?(-?)0*([0-9])"), "e$1$2");
}

std::string default_text(const nlohmann::json& value) {
  if (value.is_number()) return number_text(value.get<double>());
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_string()) return value.get<std::string>();
  return "—";
}

std::string format_key_row(const std::string& path, const std::string& type, const std::string& default_text,
                           const std::string& meaning, KeySection section, const std::string& when_to_touch) {
  std::string row = "| `" + path + "` | " + type + " | " + default_text + " | " + meaning + " |";
  if (section == KeySection::kAdvanced) row += " " + when_to_touch + " |";
  return row;
}

}  // namespace strandfem
