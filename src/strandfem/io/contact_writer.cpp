#include "strandfem/io/contact_writer.hpp"

#include <fmt/format.h>

#include <cmath>

namespace strandfem {

namespace {
bool active(const CaseDefinition& c) { return c.model.contact_settings.enabled && c.output.contacts; }
}  // namespace

ContactWriter::ContactWriter(std::filesystem::path directory, const CaseDefinition& c, bool resuming)
    : directory_(std::move(directory)), case_(c) {
  if (!active(c) || resuming) return;
  csv_.open(directory_ / "contacts.csv");
  // Line contacts carry forces per unit length (N/mm), point contacts forces (N): see force_unit.
  csv_.stream() << "step,increment,load_factor,kind,wire_a,wire_b,layer_a,layer_b,element_a,element_b,xi,eta,x_mm,y_mm,z_mm,"
          "angle_deg,gap_mm,normal_force,q1,q2,force_unit,status,slip_mm,slip_since_reversal_mm,dissipated_energy_Nmm,"
          "interface,mu1,mu2\n";
  csv_.end_row();
}

void ContactWriter::save_state(ArchiveWriter& out) const {
  out.section("contacts.csv");
  csv_.save_length(out);
  out.vector(frames_);
}

void ContactWriter::restore_state(ArchiveReader& in) {
  in.section("contacts.csv");
  csv_.resume_from(in, directory_ / "contacts.csv", active(case_));
  in.vector(frames_);
}

void ContactWriter::on_increment(const StaticAnalysis& analysis, const IncrementReport& report, int increment_count,
                                 double load_factor) {
  if (!active(case_)) return;
  const bool step_end = report.step_fraction >= 1.0 - 1e-12;
  if (increment_count % case_.output.contacts_every != 0 && !step_end) return;
  const Model& model = analysis.model();
  const ContactSet& contacts = analysis.model_state().contacts;
  for (std::size_t i = 0; i < contacts.points().size(); ++i) {
    const ContactPoint& p = contacts.points()[i];
    const ContactResponse& r = contacts.responses()[i];
    if (r.status == ContactStatus::kOpen) continue;
    const Vec3& x = r.position;
    csv_.stream() << fmt::format("{},{},{:.8g},{},{},{},{},{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.4f},{:.6e},{:.6e},{:.6e},{:.6e},{},{},{:.6e},{:.6e},{:.6e},{},{:.6g},{:.6g}\n",
                        report.step + 1, report.increment, load_factor, to_string(p.kind), p.wire_a, p.wire_b,
                        model.mesh.wires[p.wire_a].layer, model.mesh.wires[p.wire_b].layer, p.element_a, r.element_b, r.xi,
                        r.eta, x.x(), x.y(), x.z(), std::atan2(x.y(), x.x()) * 180.0 / M_PI, r.gap, r.normal_force, r.q1,
                        r.q2, p.kind == ContactKind::kLine ? "N/mm" : "N", to_string(r.status), p.history.slip,
                        p.history.slip_since_reversal, p.history.dissipated_energy,
                        to_string(contact_interface(model.mesh.wires[p.wire_a].layer, model.mesh.wires[p.wire_b].layer)),
                        p.mu1, p.mu2);
    csv_.end_row();
  }
}

void ContactWriter::write_vtu(const StaticAnalysis& analysis, const std::string& name, double time) {
  if (!active(case_)) return;
  const ContactSet& contacts = analysis.model_state().contacts;
  std::vector<int> closed;
  for (std::size_t i = 0; i < contacts.points().size(); ++i)
    if (contacts.responses()[i].status != ContactStatus::kOpen) closed.push_back(static_cast<int>(i));
  WholeFile file(directory_ / name);
  std::ostream& out = file.stream();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << closed.size() << "\" NumberOfCells=\"" << closed.size() << "\">\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int i : closed) {
    const Vec3& x = contacts.responses()[i].position;
    out << fmt::format("{:.9g} {:.9g} {:.9g}\n", x.x(), x.y(), x.z());
  }
  out << "</DataArray>\n</Points>\n<PointData>\n";
  auto array = [&](const char* array_name, auto value) {
    out << "<DataArray type=\"Float64\" Name=\"" << array_name << "\" format=\"ascii\">\n";
    for (int i : closed) out << fmt::format("{:.9g}\n", static_cast<double>(value(contacts.points()[i], contacts.responses()[i])));
    out << "</DataArray>\n";
  };
  array("normal_force", [](const ContactPoint&, const ContactResponse& r) { return r.normal_force; });
  array("q1", [](const ContactPoint&, const ContactResponse& r) { return r.q1; });
  array("q2", [](const ContactPoint&, const ContactResponse& r) { return r.q2; });
  array("gap_mm", [](const ContactPoint&, const ContactResponse& r) { return r.gap; });
  array("status", [](const ContactPoint&, const ContactResponse& r) { return static_cast<int>(r.status); });
  array("line_contact", [](const ContactPoint& p, const ContactResponse&) { return p.kind == ContactKind::kLine ? 1 : 0; });
  array("slip_mm", [](const ContactPoint& p, const ContactResponse&) { return p.history.slip; });
  array("slip_since_reversal_mm", [](const ContactPoint& p, const ContactResponse&) { return p.history.slip_since_reversal; });
  array("dissipated_energy_Nmm", [](const ContactPoint& p, const ContactResponse&) { return p.history.dissipated_energy; });
  out << "</PointData>\n<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < closed.size(); ++i) out << i << "\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 1; i <= closed.size(); ++i) out << i << "\n";
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < closed.size(); ++i) out << "1\n";  // VTK_VERTEX
  out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  file.commit();
  frames_.emplace_back(time, name);
  WholeFile pvd_file(directory_ / "contacts.pvd");
  std::ostream& pvd = pvd_file.stream();
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : frames_) pvd << "<DataSet timestep=\"" << fmt::format("{:.9g}", t) << "\" file=\"" << file << "\"/>\n";
  pvd << "</Collection>\n</VTKFile>\n";
  pvd_file.commit();
}

nlohmann::json ContactWriter::summary(const StaticAnalysis& analysis) {
  const ContactSet& contacts = analysis.model_state().contacts;
  nlohmann::json j;
  j["enabled"] = contacts.enabled();
  if (!contacts.enabled()) return j;
  int line_closed = 0, point_closed = 0, slipping = 0;
  for (std::size_t i = 0; i < contacts.points().size(); ++i) {
    const ContactResponse& r = contacts.responses()[i];
    if (r.status == ContactStatus::kOpen) continue;
    (contacts.points()[i].kind == ContactKind::kLine ? line_closed : point_closed)++;
    if (r.status == ContactStatus::kSlip) ++slipping;
  }
  j["lateral_pairs"] = contacts.lateral_pair_count();
  j["radial_pairs"] = contacts.radial_point_count();
  j["line_points"] = contacts.line_point_count();
  j["closed_line_points"] = line_closed;
  j["closed_radial_points"] = point_closed;
  j["slipping_points"] = slipping;
  j["searches"] = contacts.search_count();
  return j;
}

}  // namespace strandfem
