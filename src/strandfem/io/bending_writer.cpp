#include "strandfem/io/bending_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "strandfem/post/analytic.hpp"

namespace strandfem {
namespace {

// The paper draws the curve over 150 mm from the load point and reads Cardinal's up to 45 mm (section 5.1).
constexpr double kRiseDistanceMm[] = {45.0, 90.0, 150.0};

// The node that carries the transverse load of the first cyclic step; the monitor node if none does.
int transverse_load_node(const CaseDefinition& c) {
  for (const LoadStep& step : c.model.steps)
    for (const NodalAction& a : step.actions)
      if (step.cycles > 0 && a.kind == NodalAction::kForce && (a.component == kUx || a.component == kUy)) return a.node;
  return c.monitor_node;
}

}  // namespace

BendingWriter::BendingWriter(const std::filesystem::path& directory, const CaseDefinition& c, bool resuming)
    : directory_(directory), case_(c) {
  active_ = has_cyclic_strand_step(c);
  if (!active_) return;
  const BendingStiffnessBounds bounds = bending_stiffness_bounds(*c.strand);
  ei_max_ = bounds.ei_max;
  ei_min_ = bounds.ei_min;
  wire_shear_stiffness_ = bounds.wire_shear_stiffness;
  load_node_ = transverse_load_node(c);
  if (resuming) return;
  curves_.open(directory / "deflection_curves.csv");
  curves_.stream() << "cycle,transverse_load_N,axial_force_N,z_mm,deflection_mm,eq32_ei_max_mm,eq32_ei_min_mm,eq32_ei_min_shear_mm,"
                      "z_from_load_mm,rise_from_load_mm,eq32_ei_max_rise_mm,eq32_ei_min_rise_mm\n";
  curves_.end_row();
}

void BendingWriter::on_increment(const StaticAnalysis& analysis, const IncrementReport& report, double axial_force,
                                 double transverse_load, double midspan_deflection) {
  if (!active_) return;
  history_.push_back({report.origin.cycle, report.origin.returning, transverse_load, midspan_deflection, axial_force,
                      analysis.model_state().contacts.dissipated_energy()});
  const bool ramp_end = report.step_fraction >= 1.0 - 1e-12;
  // loops.csv is rewritten whenever a cycle closes, so that a long run shows its loops before it ends or stops.
  if (report.origin.cycle > 0 && report.origin.returning && ramp_end) finish();
  const bool peak = report.origin.cycle > 0 && !report.origin.returning && ramp_end;
  if (peak) record_peak_curve(analysis, report.origin.cycle, axial_force, transverse_load);
}

void BendingWriter::record_peak_curve(const StaticAnalysis& analysis, int cycle, double axial_force, double transverse_load) {
  // The core's transverse deflection along the strand beside eq. 3.2 (x from the nearer clamp's edge). The shear
  // form is taken on the span as the tension stretched it: the sections' laws are per reference length, so on the
  // current length they act as EI and S times the stretch (docs/theory.md, "Deflection references with shear").
  const Model& model = analysis.model();
  const double length = case_.axial_length, span = bent_span();
  const std::vector<int>& core = model.mesh.wires[0].nodes;
  const double current_length = analysis.state()[core.back()].position.z() - analysis.state()[core.front()].position.z();
  const double stretch = (current_length - (length - span)) / span;  // of the bent span: clamps and saddle stay rigid
  auto deflection_of = [&](int node) {
    const Vec3 u = analysis.state()[node].position - model.mesh.nodes[node].reference.position;
    return std::hypot(u.x(), u.y());
  };
  auto eq32 = [&](double ei, double x) { return tensioned_beam_deflection(transverse_load, axial_force, ei, span, x); };
  // From the load point as the paper draws it: the rise of each point below the load point (eq. 3.2 likewise).
  const double load_z = model.mesh.nodes[load_node_].reference.position.z(), load_x = bent_x(load_z);
  const double load_deflection = deflection_of(load_node_);
  std::vector<CurveSample> curve;
  std::vector<DeflectionPoint> points;
  for (const int node : core) {
    const double z = model.mesh.nodes[node].reference.position.z(), x = bent_x(z);
    const double deflection = deflection_of(node);
    const double ei_max_curve = eq32(ei_max_, x), ei_min_curve = eq32(ei_min_, x);
    const double ei_min_shear_curve =
        tensioned_timoshenko_deflection(transverse_load, axial_force, stretch * ei_min_, stretch * wire_shear_stiffness_,
                                        stretch * span, stretch * x);
    curves_.stream() << fmt::format("{},{:.8g},{:.8g},{:.6f},{:.8g},{:.8g},{:.8g},{:.8g},{:.6f},{:.8g},{:.8g},{:.8g}\n", cycle,
                                    transverse_load, axial_force, z, deflection, ei_max_curve, ei_min_curve, ei_min_shear_curve,
                                    z - load_z, load_deflection - deflection, eq32(ei_max_, load_x) - ei_max_curve,
                                    eq32(ei_min_, load_x) - ei_min_curve);
    curve.push_back({x, deflection, ei_max_curve, std::max(ei_min_curve, ei_min_shear_curve)});
    points.push_back({z, deflection});
  }
  CurveCheckAtPeak check{cycle, check_curve_bounds(curve), check_curve_bounds(curve, case_.output.clamp_edge_offset), {}};
  for (int i = 0; i < kRiseDistances; ++i) {
    const double d = kRiseDistanceMm[i];
    const double x = bent_x(load_z - d);
    check.from_load_point[i] = {d, rise_from_load_point(points, load_z, d), eq32(ei_max_, load_x) - eq32(ei_max_, x),
                                eq32(ei_min_, load_x) - eq32(ei_min_, x)};
  }
  curves_.end_row();
  curve_checks_.push_back(check);
}

double BendingWriter::bent_span() const { return case_.axial_length - 2 * case_.clamp_length - case_.saddle_length; }

double BendingWriter::bent_x(double z) const {
  const double from_clamp = std::min(z, case_.axial_length - z);
  return std::clamp(from_clamp - case_.clamp_length, 0.0, 0.5 * bent_span());
}

namespace {

nlohmann::json curve_check_json(const CurveBoundsCheck& c) {
  return {{"nodes", c.nodes},
          {"within", c.within},
          {"largest_excess_mm", c.largest_excess},
          {"largest_excess_x_mm", c.largest_excess_x},
          {"largest_excess_relative", c.largest_excess_relative},
          {"largest_shortfall_mm", c.largest_shortfall},
          {"largest_shortfall_x_mm", c.largest_shortfall_x}};
}

}  // namespace

nlohmann::json BendingWriter::finish() {
  if (!active_) return nullptr;
  const std::vector<HysteresisLoop> loops = hysteresis_loops(history_);
  WholeFile file(directory_ / "loops.csv");
  std::ostream& out = file.stream();
  out << "cycle,area_Nmm,friction_dissipation_Nmm,peak_load_N,peak_deflection_mm,start_deflection_mm,end_deflection_mm,"
         "secant_stiffness_N_per_mm,secant_ei_Nm2,loading_tangent_N_per_mm,unloading_tangent_N_per_mm,eq31_ei_max_mm,eq31_ei_min_mm,steady,"
         "area_change,friction_dissipation_change,peak_deflection_change,return_loop_area_Nmm,return_loop_friction_dissipation_Nmm\n";
  nlohmann::json rows = nlohmann::json::array();
  const double length = bent_span();
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const HysteresisLoop& l = loops[i];
    const double tension = l.peak_tension;
    const double travel = l.peak_deflection - l.start_deflection;
    const double secant_ei = tension > 0 ? equivalent_bending_stiffness(travel / l.peak_load, tension, length) : 0.0;
    const double y_max = tension > 0 ? tensioned_beam_midspan_deflection(l.peak_load, tension, ei_max_, length) : 0.0;
    const double y_min = tension > 0 ? tensioned_beam_midspan_deflection(l.peak_load, tension, ei_min_, length) : 0.0;
    const bool steady = i > 0 && loop_is_steady(loops[i - 1], l, case_.output.steady_tolerance);
    nlohmann::json row = {{"cycle", l.cycle}, {"area_Nmm", l.area}, {"friction_dissipation_Nmm", l.friction_dissipation},
                          {"peak_load_N", l.peak_load}, {"peak_deflection_mm", l.peak_deflection}, {"secant_ei_Nm2", 1e-6 * secant_ei},
                          {"eq31_ei_max_mm", y_max}, {"eq31_ei_min_mm", y_min},
                          {"peak_within_eq31", y_max <= l.peak_deflection && l.peak_deflection <= y_min}, {"steady", steady}};
    std::string changes = ",,";  // the first cycle has no previous one
    if (i > 0) {
      const CycleChange change = cycle_change(loops[i - 1], l);
      changes = fmt::format("{:.6g},{:.6g},{:.6g}", change.area, change.friction_dissipation, change.peak_deflection);
      row["change"] = {{"area", change.area}, {"friction_dissipation", change.friction_dissipation},
                       {"peak_deflection", change.peak_deflection}};
    }
    std::string return_loop = ",";  // none for the first cycle
    if (l.has_return_loop) {
      return_loop = fmt::format("{:.8g},{:.8g}", l.return_loop_area, l.return_loop_friction_dissipation);
      row["return_loop"] = {{"area_Nmm", l.return_loop_area}, {"friction_dissipation_Nmm", l.return_loop_friction_dissipation}};
    }
    out << fmt::format("{},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{},{},{}\n", l.cycle,
                       l.area, l.friction_dissipation, l.peak_load, l.peak_deflection, l.start_deflection,
                       l.end_deflection, l.secant_stiffness, 1e-6 * secant_ei, l.loading_tangent, l.unloading_tangent,
                       y_max, y_min, steady ? 1 : 0, changes, return_loop);
    rows.push_back(row);
  }
  file.commit();
  // Eq. 3.2's check at each peak: every interior core node, and those at or beyond the clamp-edge offset.
  nlohmann::json curves = nlohmann::json::array();
  for (const CurveCheckAtPeak& c : curve_checks_) {
    nlohmann::json rises = nlohmann::json::array();
    for (const LoadPointRise& r : c.from_load_point)
      rises.push_back({{"distance_mm", r.distance}, {"rise_mm", r.rise}, {"eq32_ei_max_mm", r.ei_max_rise}, {"eq32_ei_min_mm", r.ei_min_rise}});
    curves.push_back({{"cycle", c.cycle},
                      {"all_nodes", curve_check_json(c.all_nodes)},
                      {"beyond_clamp_edge", curve_check_json(c.beyond_clamp_edge)},
                      {"from_load_point", rises}});
  }
  return {{"ei_max_Nm2", 1e-6 * ei_max_},  {"ei_min_Nm2", 1e-6 * ei_min_},
          {"loops", rows},                {"steady_tolerance", case_.output.steady_tolerance},
          {"deflection_curves", curves}};
}

void BendingWriter::save_state(ArchiveWriter& out) const {
  out.section("bending");
  curves_.save_length(out);
  out.vector(history_);
  out.vector(curve_checks_);
}

void BendingWriter::restore_state(ArchiveReader& in) {
  in.section("bending");
  curves_.resume_from(in, directory_ / "deflection_curves.csv", active_);
  history_ = in.vector<LoadDeflectionPoint>();
  curve_checks_ = in.vector<CurveCheckAtPeak>();
}

}  // namespace strandfem
