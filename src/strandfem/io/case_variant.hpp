// Case variants for parameter sweeps: one key of a case file set to another value.
#pragma once
#include <string>

namespace strandfem {

// The case file text with the key at `key_path` (dot-separated: map keys, or 0-based indices into lists, e.g.
// `contact.friction` or `strand.layers.1.lay_angle`) set to `value`, read as YAML (a number, a word, a flow list).
// Every key on the path but the last must exist; the last may be new in its map. Throws CaseError naming the
// path when it does not lead anywhere. Comments are not kept.
std::string set_case_key(const std::string& case_text, const std::string& key_path, const std::string& value);

// A name for a folder from a variant's key and value: `contact.friction=0.5`, with characters other than letters,
// digits and `._=-` replaced by `_`.
std::string variant_folder_name(const std::string& key_path, const std::string& value);

}  // namespace strandfem
