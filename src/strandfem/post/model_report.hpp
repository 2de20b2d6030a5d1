// Model sizes and analytic references of a case, as JSON (the `info` command and summary.json).
#pragma once
#include <nlohmann/json.hpp>

#include "strandfem/io/case_file.hpp"

namespace strandfem {

// nodes, elements, dofs, per-layer geometry (radius, clearance, elements per wire), EImax/EImin (N m^2),
// linear axial stiffness (N) for fixed and free ends, metallic area, mass per length, paper comparison.
nlohmann::json model_report(const CaseDefinition& c);

}  // namespace strandfem
