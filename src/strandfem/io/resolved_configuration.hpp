// The resolved configuration summary.json records beside the case text: every default a run took for its strand,
// mesh, materials, steps and output.
#pragma once
#include <nlohmann/json.hpp>

#include "strandfem/io/case_file.hpp"

namespace strandfem {

// Writes "strand", "mesh", "materials", "steps" and "output" into `resolved` (strand and materials for strand
// cases only: a beam case's lines and sections are its text). The keys are the case file's; what the model derives
// from them (layer radii, clearances) is summary.json's `layers`.
void add_resolved_model(const CaseDefinition& c, nlohmann::json& resolved);

}  // namespace strandfem
