#include "strandfem/post/run_report.hpp"

#include <fmt/format.h>

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
  if (summary.contains("bending") && summary["bending"].contains("loops")) {
    const nlohmann::json& loops = summary["bending"]["loops"];
    if (loops.empty()) text += "bending: no cycle closed\n";
    for (const nlohmann::json& loop : loops) text += cycle_line(loop);
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
  const auto field = [](const nlohmann::json& j, const char* key) {
    return j.contains(key) && j[key].is_number() ? fmt::format("{:.8g}", j[key].get<double>()) : std::string();
  };
  std::string text = summary.value("status", "");
  const nlohmann::json none = nlohmann::json::object();
  const nlohmann::json& axial = summary.contains("axial") ? summary["axial"] : none;
  for (const char* key : {"axial_strain", "axial_force_N", "secant_stiffness_N", "relative_to_theory"}) text += "," + field(axial, key);
  const bool bent = summary.contains("bending") && summary["bending"].contains("loops") && !summary["bending"]["loops"].empty();
  if (!bent) return text + ",,,,,,";
  const nlohmann::json& loops = summary["bending"]["loops"];
  const nlohmann::json& last = loops.back();
  text += "," + std::to_string(loops.size());
  for (const char* key : {"peak_load_N", "peak_deflection_mm", "area_Nmm", "secant_ei_Nm2"}) text += "," + field(last, key);
  return text + "," + (last.contains("return_loop") ? field(last["return_loop"], "area_Nmm") : std::string());
}

}  // namespace strandfem
