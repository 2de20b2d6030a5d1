#include "strandfem/io/yaml_document.hpp"

#include <filesystem>
#include <fstream>
#include <map>

#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {
namespace {

// YAML 1.2 c-printable beyond ASCII: x85, [xA0-xD7FF], [xE000-xFFFD], [x10000-x10FFFF].
bool printable(char32_t c) {
  if (c < 0x80) return c == 0x09 || c == 0x0A || c == 0x0D || (c >= 0x20 && c <= 0x7E);
  return c == 0x85 || (c >= 0xA0 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) || c >= 0x10000;
}

// "file:line:column" of a byte offset in the text.
std::string position_of(const std::string& path, const std::string& text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return path + ":" + std::to_string(line) + ":" + std::to_string(column);
}

std::string position_of(const std::string& path, const YAML::Mark& mark) {
  if (mark.line < 0) return path;
  return path + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

std::string read_text(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) throw CaseError(path + ": cannot open the case file (no such file)");
  if (std::filesystem::is_directory(status)) throw CaseError(path + ": is a directory, not a case file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(path + ": cannot open the case file (permission?)");
  std::string text;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxCaseFileBytes)
      throw CaseError(path + ": larger than " + std::to_string(kMaxCaseFileBytes >> 20) + " MiB: not a case file");
  }
  if (in.bad()) throw CaseError(path + ": cannot read the case file");
  return text;
}

// Walks the parsed tree once, before any key is read: unique scalar keys, UTF-8 scalars, bounded depth and size.
class DocumentChecker {
 public:
  explicit DocumentChecker(const std::string& path) : path_(path) {}

  void walk(const YAML::Node& node, const std::string& key_path, int depth) {
    if (++visited_ > kMaxYamlNodes)
      fail(node.Mark(), key_path, "the document expands to more than " + std::to_string(kMaxYamlNodes) + " nodes (aliases?)");
    if (depth > kMaxYamlDepth) fail(node.Mark(), key_path, "nested deeper than " + std::to_string(kMaxYamlDepth) + " levels");
    if (node.IsScalar()) {
      if (first_invalid_utf8(node.Scalar(), false) != std::string::npos) fail(node.Mark(), key_path, "text is not valid UTF-8");
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) walk(node[i], key_path + "[" + std::to_string(i) + "]", depth + 1);
    } else if (node.IsMap()) {
      std::map<std::string, YAML::Mark> seen;
      for (const auto& entry : node) {
        if (!entry.first.IsScalar()) fail(entry.first.Mark(), key_path, "a mapping key must be a plain name, not a list or mapping");
        const std::string& key = entry.first.Scalar();
        const std::string child = key_path.empty() ? key : key_path + "." + key;
        if (first_invalid_utf8(key, false) != std::string::npos) fail(entry.first.Mark(), key_path, "key is not valid UTF-8");
        const auto [it, inserted] = seen.emplace(key, entry.first.Mark());
        if (!inserted)
          fail(entry.first.Mark(), child,
               "duplicate key: given at lines " + std::to_string(it->second.line + 1) + " and " +
                   std::to_string(entry.first.Mark().line + 1) + " (YAML keeps one silently; remove one)");
        walk(entry.second, child, depth + 1);
      }
    }
  }

 private:
  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& key_path, const std::string& what) const {
    throw CaseError(position_of(path_, mark) + ": " + (key_path.empty() ? "(top level)" : key_path) + ": " + what);
  }

  const std::string& path_;
  std::size_t visited_ = 0;
};

}  // namespace

std::size_t first_invalid_utf8(const std::string& text, bool printable_only) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    char32_t code = 0, low = 0x80, high = 0xBF;  // bounds of the second byte (excludes overlongs, surrogates)
    if (lead < 0x80) length = 1, code = lead;
    else if (lead >= 0xC2 && lead <= 0xDF) length = 2, code = lead & 0x1F;
    else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3, code = lead & 0x0F;
      if (lead == 0xE0) low = 0xA0;
      if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4, code = lead & 0x07;
      if (lead == 0xF0) low = 0x90;
      if (lead == 0xF4) high = 0x8F;
    } else {
      return i;
    }
    if (i + length > text.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      const unsigned char b = byte(i + k);
      if (b < (k == 1 ? low : 0x80) || b > (k == 1 ? high : 0xBF)) return i;
      code = (code << 6) | (b & 0x3F);
    }
    if (printable_only && !printable(code)) return i;
    i += length;
  }
  return std::string::npos;
}

YAML::Node load_yaml_document(const std::string& path) { return parse_yaml_document(read_text(path), path); }

YAML::Node parse_yaml_document(const std::string& text, const std::string& path) {
  if (text.size() > kMaxCaseFileBytes)
    throw CaseError(path + ": larger than " + std::to_string(kMaxCaseFileBytes >> 20) + " MiB: not a case file");
  if (const std::size_t bad = first_invalid_utf8(text, true); bad != std::string::npos)
    throw CaseError(position_of(path, text, bad) +
                    ": not a UTF-8 text file (byte " + std::to_string(static_cast<unsigned char>(text[bad])) +
                    " is not valid UTF-8 or is a control character)");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw CaseError(position_of(path, e.mark) + ": not valid YAML: " + e.msg);
  }
  DocumentChecker(path).walk(root, "", 0);
  return root;
}

}  // namespace strandfem
