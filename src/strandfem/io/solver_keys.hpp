// The case file's `solver:` mapping (tolerances, iteration limits, linear solver, predictor, stabilization).
#pragma once
#include <nlohmann/json.hpp>

#include "strandfem/io/setting_keys.hpp"
#include "strandfem/io/yaml_reader.hpp"
#include "strandfem/solver/model.hpp"

namespace strandfem {

// The keys of `solver:`, each with its type, range, default (SolverOptions{}) and meaning.
const std::vector<SettingKey<SolverOptions>>& solver_key_table();

// Reads `solver:` (docs/case-files.md) into `options`, over the defaults it holds; throws CaseError naming the key.
// The options' cross-checks (SolverOptions::validate) stay with the caller, after the whole case is read.
void parse_solver_options(const YamlReader& reader, const YAML::Node& node, SolverOptions& options);

// The options as the run uses them (defaults filled in), for summary.json.
nlohmann::json resolved_solver_options(const SolverOptions& options);

}  // namespace strandfem
