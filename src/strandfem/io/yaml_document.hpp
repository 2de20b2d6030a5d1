// Loading a case file into a YAML tree that the key-by-key reader can trust: the file is a readable regular file
// of bounded size in UTF-8, it parses, and every mapping has unique scalar keys. All failures are CaseError.
#pragma once
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>

namespace strandfem {

// Case files are hand-written text: anything larger is not a case file (and would only cost memory).
constexpr std::size_t kMaxCaseFileBytes = 16u << 20;
// Nesting deeper than this is no case file either; it also stops the walk of a self-referencing alias.
constexpr int kMaxYamlDepth = 64;
// Aliases can make a small file expand to an exponential tree ("billion laughs"): the walk stops here.
constexpr std::size_t kMaxYamlNodes = 1000000;

// Position of the first byte that is not valid UTF-8 or not a YAML printable character (tab, line feed and
// carriage return are the only control characters allowed), or npos when the text is clean.
std::size_t first_invalid_utf8(const std::string& text, bool printable_only);

// Reads, parses and checks the case file at `path`. Throws CaseError (file:line:column where known) when the
// path is not a regular file, is unreadable or too large, is not UTF-8, is not valid YAML, when a mapping repeats
// a key (naming both lines) or has a key that is not a scalar, or when the tree is too deep or too large.
YAML::Node load_yaml_document(const std::string& path);
// The same checks on case-file text held in memory; `name` stands for the file in messages.
YAML::Node parse_yaml_document(const std::string& text, const std::string& name);

}  // namespace strandfem
