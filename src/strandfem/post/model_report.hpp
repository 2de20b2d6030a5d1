// Model sizes and analytic references of a case, as JSON (the `info` command and summary.json).
#pragma once
#include <nlohmann/json.hpp>

#include "strandfem/io/case_file.hpp"

namespace strandfem {

// nodes, elements, dofs, per-layer geometry (radius, clearance, elements per wire), EImax/EImin (N m^2),
// linear axial stiffness (N) for fixed and free ends, metallic area, mass per length, paper comparison.
nlohmann::json model_report(const CaseDefinition& c);

// A strand's Poffenberger–Swart reference for a tension (N) and a peak-to-peak bending amplitude yb (mm) at 89 mm from
// the last point of contact: p, K and the outer wires' stress amplitude, with the EImin, E and d they use.
nlohmann::json poffenberger_swart_report(const StrandSpec& strand, double tension, double yb);

}  // namespace strandfem
