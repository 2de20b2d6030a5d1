// The case file's `output:` mapping (which files a run writes, how often, and what the bending results measure).
#pragma once
#include <vector>

#include "strandfem/io/case_file.hpp"
#include "strandfem/io/setting_keys.hpp"

namespace strandfem {

// The keys of `output:` but `monitor` (a node selector: monitor_key_table), each with its type, range, default
// and meaning. `clamp_edge_offset` is checked against the strand's length by the case reader.
const std::vector<SettingKey<OutputOptions>>& output_key_table();

}  // namespace strandfem
