// The end-of-run report: what a run measured beside the theory, as lines for the terminal, read from summary.json.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace strandfem {

// Title, status, increments and wall time; then for a bent strand, per cycle, the peak deflection beside eq. 3.1's
// EImax and EImin values, the loop and the secant EI; for a strand pulled or twisted only, the final strain and
// force and the secant slope against the linear theory for its ends. Every line ends with '\n'.
std::string end_of_run_report(const nlohmann::json& summary);

// The results a sweep tabulates per variant (sweep.csv), from its summary.json: the status, the axial response
// at the end and, for bent strands, the number of cycles and the last cycle's peak, loop, secant EI and return
// loop. Empty fields where the run measured nothing of the kind.
std::string sweep_result_header();
std::string sweep_result_fields(const nlohmann::json& summary);

}  // namespace strandfem
