#include "strandfem/io/profile_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>

namespace strandfem {

ProfileWriter::ProfileWriter(const std::filesystem::path& directory, const CaseDefinition& c, bool resuming)
    : directory_(directory), case_(c) {
  active_ = has_cyclic_strand_step(c);
  if (!active_) return;
  Vec3 load = Vec3::Zero();
  for (const LoadStep& s : c.model.steps)
    if (s.cycles > 0)
      for (const NodalAction& a : s.actions)
        if (a.kind == NodalAction::kForce && a.component < 2) load[a.component] += a.value;
  if (std::hypot(load.x(), load.y()) > 0) load_angle_degrees_ = std::atan2(load.y(), load.x()) * 180.0 / std::numbers::pi;
  if (resuming) return;
  wires_.open(directory / "wire_profiles.csv");
  wires_.stream() << "cycle,wire,layer,node,z_mm,z_from_midspan_mm,angle_deg,plane,axial_force_N,delta_axial_force_N\n";
  wires_.end_row();
  contacts_.open(directory / "contact_profiles.csv");
  contacts_.stream() << "cycle,point,kind,layer_a,layer_b,z_mm,z_from_midspan_mm,angle_deg,plane,normal_force,delta_normal_force,"
                        "tangential_force,delta_tangential_force,force_unit,slip_mm,delta_slip_mm,tangential_displacement_mm,"
                        "delta_tangential_displacement_mm,map_status\n";
  contacts_.end_row();
}

void ProfileWriter::on_increment(const StaticAnalysis& analysis, const IncrementReport& report) {
  if (!active_) return;
  const Model& model = analysis.model();
  const bool ramp_end = report.step_fraction >= 1.0 - 1e-12;
  const bool loading = report.origin.cycle > 0 && !report.origin.returning;
  if (loading) tracker_.observe(contact_statuses(analysis.model_state()));
  if (loading && ramp_end) {
    write(tracker_.at_peak(report.origin.cycle, take_strand_snapshot(model, analysis.model_state())));
  } else if (ramp_end) {
    // The state a following loading half starts from (V = 0 after the tension ramp or a returning half).
    tracker_.set_start(take_strand_snapshot(model, analysis.model_state()));
  }
}

void ProfileWriter::write(const BendingProfiles& p) {
  const double midspan = 0.5 * case_.axial_length;
  for (const WireProfileRow& r : p.wires) {
    const WireForceSample& s = r.at_peak;
    wires_.stream() << fmt::format("{},{},{},{},{:.6f},{:.6f},{:.4f},{},{:.8e},{:.8e}\n", p.cycle, s.wire, s.layer, s.node, s.z,
                                   s.z - midspan, s.angle_degrees, to_string(plane_region(s.angle_degrees, s.radius, load_angle_degrees_)),
                                   s.axial_force, r.axial_force_change);
  }
  wires_.end_row();
  struct Totals {
    std::map<std::string, int> statuses;
    double normal_force = 0, tangential_force = 0;
    double dissipated_energy = 0;  // over the loading half, N mm
    int closed = 0;
  };
  std::map<std::string, Totals> interfaces;
  for (const ContactProfileRow& r : p.contacts) {
    const ContactSample& s = r.at_peak;
    const bool line = s.kind == static_cast<int>(ContactKind::kLine);
    contacts_.stream() << fmt::format("{},{},{},{},{},{:.6f},{:.6f},{:.4f},{},{:.6e},{:.6e},{:.6e},{:.6e},{},{:.6e},{:.6e},{:.6e},{:.6e},{}\n", p.cycle,
                                      r.point, line ? "line" : "point", s.layer_a, s.layer_b, s.z, s.z - midspan, s.angle_degrees,
                                      to_string(plane_region(s.angle_degrees, s.radius, load_angle_degrees_)), s.normal_force,
                                      r.normal_force_change, s.tangential_force, r.tangential_force_change, line ? "N/mm" : "N",
                                      s.slip, r.slip_change, s.tangential_displacement, r.tangential_displacement_change,
                                      to_string(r.map_status));
    Totals& t = interfaces[fmt::format("{} {}-{}", line ? "line" : "point", std::min(s.layer_a, s.layer_b),
                                       std::max(s.layer_a, s.layer_b))];
    ++t.statuses[to_string(r.map_status)];
    t.dissipated_energy += r.dissipated_energy_change;
    if (r.map_status == MapStatus::kOpen) continue;
    ++t.closed;
    t.normal_force += s.normal_force;
    t.tangential_force += s.tangential_force;
  }
  contacts_.end_row();
  nlohmann::json block = {{"cycle", p.cycle}};
  for (const auto& [name, t] : interfaces) {
    nlohmann::json j = t.statuses;
    j["mean_normal_force"] = t.closed ? t.normal_force / t.closed : 0.0;
    j["mean_tangential_force"] = t.closed ? t.tangential_force / t.closed : 0.0;
    j["loading_friction_dissipation_Nmm"] = t.dissipated_energy;
    block["interfaces"][name] = j;
  }
  summary_.push_back(block);
}

// Only cyclic cases carry this section, so checkpoints of other cases read as before.
void ProfileWriter::save_state(ArchiveWriter& out) const {
  if (!active_) return;
  out.section("profiles");
  wires_.save_length(out);
  contacts_.save_length(out);
  out.vector(tracker_.start().wires);
  out.vector(tracker_.start().contacts);
  out.vector(tracker_.stuck());
  out.string(summary_.dump());
}

void ProfileWriter::restore_state(ArchiveReader& in) {
  if (!active_) return;
  in.section("profiles");
  wires_.resume_from(in, directory_ / "wire_profiles.csv", active_);
  contacts_.resume_from(in, directory_ / "contact_profiles.csv", active_);
  StrandSnapshot start;
  start.wires = in.vector<WireForceSample>();
  start.contacts = in.vector<ContactSample>();
  std::vector<char> stuck = in.vector<char>();
  tracker_.restore(std::move(start), std::move(stuck));
  summary_ = nlohmann::json::parse(in.string());
}

}  // namespace strandfem
