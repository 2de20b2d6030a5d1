#include "strandfem/post/run_report.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace strandfem {
namespace {

double number(const nlohmann::json& j, const char* key) { return j.contains(key) && j[key].is_number() ? j[key].get<double>() : 0.0; }

std::string percent(double relative) { return fmt::format("{:+.2f} %", 100.0 * relative); }

std::string cycle_line(const nlohmann::json& loop) {
  std::string line = fmt::format("cycle {}: peak {:.4g} mm at {:.5g} N (eq. 3.1: {:.4g} mm with EImax, {:.4g} mm with EImin), loop {:.4g} N m, "
                                 "secant EI {:.4g} N m2",
                                 loop.value("cycle", 0), number(loop, "peak_deflection_mm"), number(loop, "peak_load_N"),
                                 number(loop, "eq31_ei_max_mm"), number(loop, "eq31_ei_min_mm"), 1e-3 * number(loop, "area_Nmm"),
                                 number(loop, "secant_ei_Nm2"));
  if (loop.contains("return_loop")) line += fmt::format(", return loop {:.4g} N m", 1e-3 * number(loop["return_loop"], "area_Nmm"));
  return line + "\n";
}

}  // namespace

std::string end_of_run_report(const nlohmann::json& summary) {
  const std::string status = summary.value("status", "unknown");
  const int threads = summary.value("threads", 1);
  std::string text = fmt::format("{}: {} after {} converged increments, {:.3g} s on {} thread{}\n", summary.value("title", "case"),
                                 status == "converged" ? "done" : status, summary.value("converged_increments", 0),
                                 number(summary, "wall_time_s"), threads, threads == 1 ? "" : "s");
  if (summary.contains("energy") && number(summary["energy"], "stabilization_energy_Nmm") > 0)
    text += fmt::format("stabilization: {:.3g} % of the work done on the strand went into it\n",
                        100 * number(summary["energy"], "stabilization_fraction"));
  // A bent strand: a cyclic step with a transverse load (an axial cycle has loops of no transverse load).
  const bool bent = summary.contains("bending") && summary["bending"].contains("loops") &&
                    std::any_of(summary["bending"]["loops"].begin(), summary["bending"]["loops"].end(),
                                [](const nlohmann::json& loop) { return number(loop, "peak_load_N") > 0; });
  if (bent) {
    for (const nlohmann::json& loop : summary["bending"]["loops"]) text += cycle_line(loop);
    return text;
  }
  if (!summary.contains("axial")) return text;
  const nlohmann::json& axial = summary["axial"];
  text += fmt::format("axial: strain {:.6g}, force {:.6g} N, torque {:.4g} N mm, end rotation {:.4g} rad\n", number(axial, "axial_strain"),
                      number(axial, "axial_force_N"), number(axial, "torque_Nmm"), number(axial, "end_rotation_rad"));
  if (axial.contains("secant_stiffness_N"))
    text += fmt::format("axial: secant slope {:.5g} MN against {:.5g} MN of the linear theory for {} ends ({})\n",
                        1e-6 * number(axial, "secant_stiffness_N"), 1e-6 * number(axial, "theory_stiffness_N"),
                        axial.value("theory_ends", ""), percent(number(axial, "relative_to_theory")));
  return text;
}

std::string sweep_result_header() {
  return "status,axial_strain,axial_force_N,secant_stiffness_N,relative_to_theory,cycles,peak_load_N,peak_deflection_mm,"
         "loop_area_Nmm,secant_ei_Nm2,return_loop_area_Nmm";
}

std::string sweep_result_fields(const nlohmann::json& summary) {
  std::string text = summary.value("status", "");
  const auto add = [&text](const nlohmann::json& j, const char* key) {
    text += ',';
    if (j.contains(key) && j[key].is_number()) text += fmt::format("{:.8g}", j[key].get<double>());
  };
  const nlohmann::json none = nlohmann::json::object();
  const nlohmann::json& axial = summary.contains("axial") ? summary["axial"] : none;
  for (const char* key : {"axial_strain", "axial_force_N", "secant_stiffness_N", "relative_to_theory"}) add(axial, key);
  const bool bent = summary.contains("bending") && summary["bending"].contains("loops") && !summary["bending"]["loops"].empty();
  if (!bent) return text + ",,,,,,";
  const nlohmann::json& loops = summary["bending"]["loops"];
  const nlohmann::json& last = loops.back();
  text += fmt::format(",{}", loops.size());
  for (const char* key : {"peak_load_N", "peak_deflection_mm", "area_Nmm", "secant_ei_Nm2"}) add(last, key);
  add(last.contains("return_loop") ? last["return_loop"] : none, "area_Nmm");
  return text;
}

}  // namespace strandfem
