#include "strandfem/io/wire_writer.hpp"

#include <fmt/format.h>

#include "strandfem/post/wire_results.hpp"

namespace strandfem {

WireWriter::WireWriter(const std::filesystem::path& directory, const CaseDefinition& c, bool resuming)
    : directory_(directory), case_(c) {
  if (!c.output.wires || resuming) return;
  csv_.open(directory / "wires.csv");
  // Resultants in the section axes (1: wire axis); z and angle are the node's reference position.
  csv_.stream() << "step,increment,load_factor,wire,layer,node,z_mm,angle_deg,radius_mm,axial_force_N,bending_moment_2_Nmm,"
          "bending_moment_3_Nmm,torque_Nmm,max_von_mises_MPa,max_plastic_strain\n";
  csv_.end_row();
}

void WireWriter::save_state(ArchiveWriter& out) const {
  out.section("wires.csv");
  csv_.save_length(out);
}

void WireWriter::restore_state(ArchiveReader& in) {
  in.section("wires.csv");
  csv_.resume_from(in, directory_ / "wires.csv", case_.output.wires);
}

void WireWriter::on_increment(const StaticAnalysis& analysis, const IncrementReport& report, int increment_count,
                              double load_factor) {
  if (!case_.output.wires) return;
  const bool step_end = report.step_fraction >= 1.0 - 1e-12;
  if (increment_count % case_.output.contacts_every != 0 && !step_end) return;
  for (const WireNodeResult& r : wire_node_results(analysis.model(), analysis.model_state())) {
    csv_.stream() << fmt::format("{},{},{:.8g},{},{},{},{:.6f},{:.4f},{:.6f},{:.8e},{:.8e},{:.8e},{:.8e},{:.6e},{:.6e}\n", report.step + 1,
                        report.increment, load_factor, r.wire, r.layer, r.node, r.z, r.angle_degrees, r.radius, r.resultants[0],
                        r.resultants[4], r.resultants[5], r.resultants[3], r.max_von_mises, r.max_plastic_strain);
    csv_.end_row();
  }
}

}  // namespace strandfem
