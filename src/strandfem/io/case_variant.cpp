#include "strandfem/io/case_variant.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <sstream>
#include <vector>

#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {

namespace {
std::vector<std::string> split_path(const std::string& key_path) {
  std::vector<std::string> parts;
  std::stringstream in(key_path);
  for (std::string part; std::getline(in, part, '.');) parts.push_back(part);
  if (key_path.empty() || key_path.back() == '.' || parts.empty())
    throw CaseError("sweep key '" + key_path + "': expected a dot-separated path such as contact.friction");
  for (const std::string& part : parts)
    if (part.empty()) throw CaseError("sweep key '" + key_path + "': empty part in the path");
  return parts;
}

bool is_index(const std::string& part) {
  return !part.empty() && part.size() < 9 &&
         std::all_of(part.begin(), part.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}
}  // namespace

std::string set_case_key(const std::string& case_text, const std::string& key_path, const std::string& value) {
  const std::vector<std::string> parts = split_path(key_path);
  YAML::Node root;
  YAML::Node replacement;
  try {
    root = YAML::Load(case_text);
    replacement = YAML::Load(value);
  } catch (const YAML::Exception& e) {
    throw CaseError("sweep key '" + key_path + "' = '" + value + "': not YAML (" + e.what() + ")");
  }
  if (!replacement.IsDefined() || replacement.IsNull())
    throw CaseError("sweep key '" + key_path + "': expected a value, got '" + value + "'");
  // Nodes are references into the document: walking with copies and assigning the last one edits root.
  YAML::Node node = root;
  std::string walked;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    const std::string here = walked.empty() ? part : walked + "." + part;
    if (node.IsSequence()) {
      if (!is_index(part) || std::stoul(part) >= node.size())
        throw CaseError("sweep key '" + key_path + "': '" + walked + "' is a list of " + std::to_string(node.size()) +
                        " entries, expected an index 0.." + std::to_string(node.size() - 1) + " for '" + part + "'");
      const std::size_t index = std::stoul(part);
      if (last) node[index] = replacement;
      else node.reset(node[index]);
    } else if (node.IsMap()) {
      if (last) {
        node[part] = replacement;
      } else {
        if (!node[part]) throw CaseError("sweep key '" + key_path + "': the case has no '" + here + "'");
        node.reset(node[part]);
      }
    } else {
      throw CaseError("sweep key '" + key_path + "': '" + walked + "' is a value, not a map or a list");
    }
    walked = here;
  }
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

std::string variant_folder_name(const std::string& key_path, const std::string& value) {
  std::string name = key_path + "=" + value;
  for (char& c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '=' || c == '-')) c = '_';
  return name;
}

}  // namespace strandfem
