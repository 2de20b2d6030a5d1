#include "strandfem/io/output_keys.hpp"

#include <limits>

namespace strandfem {

const std::vector<SettingKey<OutputOptions>>& output_key_table() {
  using O = OutputOptions;
  static const std::vector<SettingKey<O>> table = [] {
    constexpr int kUnbounded = std::numeric_limits<int>::max();
    // An explicit count stays when `every` changes.
    auto contacts_every = integer_key("contacts_every", &O::contacts_every, 1, kUnbounded,
                                      "their rows every n-th increment, and always at the end of each step")
                              .default_is("`output.every`");
    contacts_every.read = [read_count = contacts_every.read](const YamlReader& reader, const YAML::Node& node, const std::string& path, O& o) {
      read_count(reader, node, path, o);
      o.contacts_every_set = true;
    };
    return keys_in_section<O>(KeySection::kPhysics, {
        integer_key("every", &O::every, 1, kUnbounded, "ParaView frame every n-th increment"),
        boolean_key("vtu", &O::vtu, "write the ParaView files"),
        boolean_key("contacts", &O::contacts, "write `contacts.csv` and the contact ParaView points").default_is("true with contact"),
        contacts_every,
        boolean_key("wires", &O::wires, "write `wires.csv` at the increments of `contacts.csv`"),
        boolean_key("checkpoint", &O::checkpoint, "write `checkpoint.bin` after every converged increment, for `--resume`"),
        number_key("clamp_edge_offset", &O::clamp_edge_offset, NumberRange::non_negative(), "mm",
                   "where the bending status maps and summary.json's `beyond_clamp_edge` check start, from each restrained end (the "
                   "paper's clamp edge, section 4.1: 22 mm for Cardinal)")
            .typed("mm, ≥ 0 and below half the length; strands"),
        number_key("steady_tolerance", &O::steady_tolerance, NumberRange::below(1), "fraction",
                   "a cycle counts as `steady` when its loop area and peak deflection differ from the previous cycle's by at most "
                   "this fraction"),
    });
  }();
  return table;
}

}  // namespace strandfem
