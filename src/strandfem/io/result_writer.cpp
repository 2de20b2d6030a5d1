#include "strandfem/io/result_writer.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "strandfem/post/wire_results.hpp"
#include "strandfem/solver/blas_kernels.hpp"
#include "strandfem/solver/mumps_processes.hpp"

namespace strandfem {
namespace {

Vec3 displacement(const StaticAnalysis& a, int node) {
  return a.state()[node].position - a.model().mesh.nodes[node].reference.position;
}
Vec3 rotation(const StaticAnalysis& a, int node) {
  return rotation_vector_from_quaternion(a.state()[node].rotation * a.model().mesh.nodes[node].reference.rotation.conjugate());
}

// The strand's axial response at the last converged increment beside the linear theory for its ends.
nlohmann::json axial_result(const HistoryRow& last, const nlohmann::json& model_info, const std::string& ends) {
  nlohmann::json axial = {{"axial_strain", last.axial_strain},
                          {"axial_force_N", last.axial_force},
                          {"torque_Nmm", last.torque},
                          {"end_rotation_rad", last.end_rotation}};
  if (!(std::abs(last.axial_strain) > 1e-12) || !model_info.contains("axial_stiffness_N")) return axial;
  const double secant = last.axial_force / last.axial_strain;
  const double theory = model_info["axial_stiffness_N"][ends == "free" ? "free_ends" : "fixed_ends"].get<double>();
  axial["secant_stiffness_N"] = secant;
  axial["theory_stiffness_N"] = theory;
  axial["theory_ends"] = ends;
  axial["relative_to_theory"] = secant / theory - 1.0;
  return axial;
}

}  // namespace

HistoryRow history_row(const CaseDefinition& c, const StaticAnalysis& analysis, const IncrementReport& report) {
  HistoryRow row;
  row.step = report.step + 1;
  row.increment = report.increment;
  row.load_factor = report.step + report.step_fraction;
  row.iterations = report.iterations;
  row.residual_norm = report.residual_norm;
  row.case_step = report.origin.step + 1;
  row.cycle = report.origin.cycle;
  row.returning = report.origin.returning;
  const auto& f = analysis.internal_forces();
  if (c.monitor_node >= 0) {
    row.monitor_displacement = displacement(analysis, c.monitor_node);
    row.monitor_force = Vec3(f[6 * c.monitor_node], f[6 * c.monitor_node + 1], f[6 * c.monitor_node + 2]);
  }
  // Loaded nodes: those carrying a force action in any step.
  Vec3 applied = Vec3::Zero();
  std::vector<bool> loaded(c.model.mesh.nodes.size(), false);
  for (const LoadStep& s : c.model.steps)
    for (const NodalAction& a : s.actions)
      if (a.kind == NodalAction::kForce && a.component < 3) loaded[a.node] = true;
  for (std::size_t n = 0; n < loaded.size(); ++n)
    if (loaded[n] && !(c.strand && static_cast<int>(n) == c.end_node))
      applied += Vec3(f[6 * n], f[6 * n + 1], f[6 * n + 2]);
  if (c.strand) {
    const int end = c.end_node, start = c.start_node;
    row.axial_strain = (displacement(analysis, end).z() - displacement(analysis, start).z()) / c.axial_length;
    row.axial_force = f[6 * end + 2];
    row.torque = f[6 * end + 5];
    row.end_rotation = rotation(analysis, end).z();
    row.transverse_load = std::hypot(applied.x(), applied.y());
    row.midspan_deflection = std::hypot(row.monitor_displacement.x(), row.monitor_displacement.y());
  } else if (c.monitor_node >= 0) {
    // Beam lines: the monitor node's axial (z) force, moment about z and rotation about z.
    row.axial_force = f[6 * c.monitor_node + 2];
    row.torque = f[6 * c.monitor_node + 5];
    row.end_rotation = rotation(analysis, c.monitor_node).z();
    row.transverse_load = applied.norm();
    row.midspan_deflection = row.monitor_displacement.norm();
  }
  return row;
}

nlohmann::json read_summary(const std::filesystem::path& folder) {
  std::ifstream in(folder / "summary.json");
  nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
  return summary.is_discarded() ? nlohmann::json::object() : summary;
}

bool is_result_file_name(std::string name) {
  const std::string partial = kPartialSuffix;
  if (name.size() > partial.size() && name.compare(name.size() - partial.size(), partial.size(), partial) == 0)
    name.resize(name.size() - partial.size());
  for (const char* fixed : {"history.csv", "displacements.csv", "summary.json", "contacts.csv", "wires.csv", "loops.csv",
                            "deflection_curves.csv", "wire_profiles.csv", "contact_profiles.csv", "checkpoint.bin", "bending_hysteresis.png", "bending_deflection.png",
                            "bending_wire_forces.png", "bending_contact_forces.png", "bending_status_maps.png", "result.pvd", "contacts.pvd"})
    if (name == fixed) return true;
  // result_NNNNN.vtu, contacts_NNNNN.vtu: five or more digits.
  for (const std::string prefix : {"result_", "contacts_"}) {
    if (name.size() < prefix.size() + 5 + 4 || name.compare(0, prefix.size(), prefix) != 0) continue;
    if (name.compare(name.size() - 4, 4, ".vtu") != 0) continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    if (digits.find_first_not_of("0123456789") == std::string::npos) return true;
  }
  return false;
}

namespace {
// Creates the folder and removes what an earlier run left in it, so that every result file there is this run's.
void take_over(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory))
    throw_output_error(directory, "cannot create the results folder" + (error ? ": " + error.message() : std::string()), 0);
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    if (!is_result_file_name(entry.path().filename().string()) || entry.is_directory()) continue;
    std::filesystem::remove(entry.path(), error);
    if (error) throw_output_error(entry.path(), "cannot remove the previous run's file: " + error.message(), 0);
  }
  if (error) throw_output_error(directory, "cannot list the results folder: " + error.message(), 0);
}
}  // namespace

ResultWriter::ResultWriter(std::filesystem::path directory, const CaseDefinition& c, nlohmann::json model_info, bool resuming)
    : directory_(std::move(directory)), case_(c), model_info_(std::move(model_info)),
      contacts_((resuming ? void() : take_over(directory_), directory_), c, resuming), wires_(directory_, c, resuming),
      bending_(directory_, c, resuming), profiles_(directory_, c, resuming) {
  nlohmann::json running = model_info_;
  running["status"] = "running";
  running["configuration"] = case_.resolved;
  write_summary(running);
  if (resuming) return;
  history_.open(directory_ / "history.csv");
  history_.stream() << "step,increment,load_factor,axial_strain,axial_force_N,torque_Nmm,end_rotation_rad,transverse_load_N,"
              "midspan_deflection_mm,monitor_ux_mm,monitor_uy_mm,monitor_uz_mm,newton_iterations,residual_norm,monitor_fx_N,monitor_fy_N,monitor_fz_N,case_step,cycle,returning\n";
  history_.end_row();
}

void ResultWriter::write_summary(const nlohmann::json& summary) const {
  WholeFile file(directory_ / "summary.json");
  file.stream() << summary.dump(2) << "\n";
  file.commit();
}

namespace {
// Counts and times of the analysis so far. After a resume the analysis' own (Newton iterations, assembly, pattern)
// include the runs before it, the linear solver's (factorizations and their times) this run only.
nlohmann::json solver_statistics(const StaticAnalysis& analysis) {
  const AnalysisStatistics& a = analysis.statistics();
  const LinearSolverStatistics& l = analysis.linear_statistics();
  return {{"newton_iterations", a.newton_iterations},
          {"factorizations", l.factorizations},
          {"krylov_solves", a.krylov_solves},
          {"krylov_iterations", a.krylov_iterations},
          {"pattern_rebuilds", a.pattern_rebuilds},
          {"rejected_extrapolations", a.rejected_extrapolations},
          {"plain_retries", a.plain_retries},
          {"stick_augmentations", a.stick_augmentations},
          {"abandoned_augmentations", a.abandoned_augmentations},
          {"searched_recoveries", a.searched_recoveries},
          {"stabilized_steps", a.stabilized_steps},
          {"limited_corrections", a.limited_corrections},
          {"double_precision_fallbacks", a.double_precision_fallbacks},
          {"force_only_acceptances", a.force_only_acceptances},
          {"assembly_seconds", a.assembly_seconds},
          {"residual_seconds", a.residual_seconds},
          {"commit_seconds", a.commit_seconds},
          {"linear_seconds", a.linear_seconds},
          {"pattern_seconds", a.pattern_seconds},
          {"factorization_seconds", l.factorization_seconds},
          {"solve_seconds", l.solve_seconds},
          {"analyses", l.analyses},
          {"analysis_seconds", l.analysis_seconds},
          {"ordering", l.ordering},
          {"blas_kernels", blas_core_name()},
          {"blas_threads", blas_thread_count()},
          {"mumps_build", mumps_build()},
          {"mumps_processes", mumps_process_count()},
          {"factor_entries", l.factor_entries},
          {"factorization_flops", l.factorization_flops}};
}
}  // namespace

nlohmann::json ResultWriter::run_summary(const StaticAnalysis& analysis, double wall_seconds) {
  nlohmann::json summary = model_info_;
  summary["wall_time_s"] = wall_seconds;
  summary["converged_increments"] = rows_.size();
  summary["linear_solver"] = analysis.linear_solver_name();
  summary["solver_statistics"] = solver_statistics(analysis);
  // Abaqus' check on its stabilization: the energy it dissipates against the work done on the model.
  const EnergyBalance& energy = analysis.energies();
  summary["energy"] = {{"external_work_Nmm", energy.external_work},
                       {"stabilization_energy_Nmm", energy.stabilization_energy},
                       {"stabilization_fraction",
                        energy.external_work > 0 ? energy.stabilization_energy / energy.external_work : 0.0}};
  summary["contacts"] = ContactWriter::summary(analysis);
  if (case_.strand && !rows_.empty()) summary["axial"] = axial_result(rows_.back(), model_info_, case_.end_type);
  if (bending_.active()) {
    summary["bending"] = bending_.finish();
    summary["bending"]["profiles"] = profiles_.summary();
    summary["bending"]["clamp_edge_offset_mm"] = case_.output.clamp_edge_offset;
  }
  summary["configuration"] = case_.resolved;
  return summary;
}

void ResultWriter::record_stop(const StaticAnalysis& analysis, double wall_seconds) {
  nlohmann::json summary = run_summary(analysis, wall_seconds);
  summary["status"] = "stopped";
  summary["message"] = "stopped on request (--stop-after, or Ctrl-C in Python) after its last converged increment; resume continues";
  write_summary(summary);
}

void ResultWriter::record_failure(const std::string& status, const std::string& message) noexcept {
  try {
    nlohmann::json summary = model_info_;
    summary["status"] = status;
    summary["message"] = message;
    summary["converged_increments"] = rows_.size();
    summary["configuration"] = case_.resolved;
    write_summary(summary);
  } catch (...) {
    // The folder is what failed: the error already on its way to the user says so.
  }
}

namespace {
void save_row(ArchiveWriter& out, const HistoryRow& r) {
  out.value(std::array<int, 6>{r.step, r.increment, r.iterations, r.case_step, r.cycle, r.returning ? 1 : 0});
  out.value(std::array<double, 8>{r.load_factor, r.axial_strain, r.axial_force, r.torque, r.end_rotation, r.transverse_load,
                                  r.midspan_deflection, r.residual_norm});
  out.vec3(r.monitor_displacement);
  out.vec3(r.monitor_force);
}
HistoryRow load_row(ArchiveReader& in) {
  HistoryRow r;
  const auto ints = in.value<std::array<int, 6>>();
  r.step = ints[0], r.increment = ints[1], r.iterations = ints[2], r.case_step = ints[3], r.cycle = ints[4];
  r.returning = ints[5] != 0;
  const auto reals = in.value<std::array<double, 8>>();
  r.load_factor = reals[0], r.axial_strain = reals[1], r.axial_force = reals[2], r.torque = reals[3];
  r.end_rotation = reals[4], r.transverse_load = reals[5], r.midspan_deflection = reals[6], r.residual_norm = reals[7];
  r.monitor_displacement = in.vec3();
  r.monitor_force = in.vec3();
  return r;
}
}  // namespace

void ResultWriter::save_state(ArchiveWriter& out) const {
  out.section("history.csv");
  history_.save_length(out);
  out.value(static_cast<std::uint64_t>(rows_.size()));
  for (const HistoryRow& r : rows_) save_row(out, r);
  out.vector(frames_);
  out.value(increments_seen_);
  out.value(last_written_);
  contacts_.save_state(out);
  wires_.save_state(out);
  bending_.save_state(out);
  profiles_.save_state(out);
}

void ResultWriter::restore_state(ArchiveReader& in) {
  in.section("history.csv");
  history_.resume_from(in, directory_ / "history.csv", true);
  rows_.resize(in.value<std::uint64_t>());
  for (HistoryRow& r : rows_) r = load_row(in);
  in.vector(frames_);
  in.value(increments_seen_);
  in.value(last_written_);
  contacts_.restore_state(in);
  wires_.restore_state(in);
  bending_.restore_state(in);
  profiles_.restore_state(in);
}

void ResultWriter::on_increment(const StaticAnalysis& analysis, const IncrementReport& report) {
  const HistoryRow r = history_row(case_, analysis, report);
  rows_.push_back(r);
  history_.stream() << fmt::format("{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{:.4e},{:.10g},{:.10g},{:.10g},{},{},{}\n",
                          r.step, r.increment, r.load_factor, r.axial_strain, r.axial_force, r.torque, r.end_rotation,
                          r.transverse_load, r.midspan_deflection, r.monitor_displacement.x(), r.monitor_displacement.y(),
                          r.monitor_displacement.z(), r.iterations, r.residual_norm, r.monitor_force.x(), r.monitor_force.y(),
                          r.monitor_force.z(), r.case_step, r.cycle, r.returning ? 1 : 0);
  history_.end_row();
  ++increments_seen_;
  contacts_.on_increment(analysis, report, increments_seen_, r.load_factor);
  wires_.on_increment(analysis, report, increments_seen_, r.load_factor);
  bending_.on_increment(analysis, report, r.axial_force, r.transverse_load, r.midspan_deflection);
  profiles_.on_increment(analysis, report);
  last_written_ = false;
  if (case_.output.vtu && increments_seen_ % case_.output.every == 0) {
    write_vtu(analysis, r.load_factor);
    last_written_ = true;
  }
}

void ResultWriter::write_vtu(const StaticAnalysis& analysis, double time) {
  const Model& model = analysis.model();
  const Mesh& mesh = model.mesh;
  const std::string name = fmt::format("result_{:05d}.vtu", frames_.size());
  WholeFile file(directory_ / name);
  std::ostream& out = file.stream();
  const std::size_t points = mesh.nodes.size(), cells = 2 * mesh.elements.size();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << points << "\" NumberOfCells=\"" << cells << "\">\n";
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const MeshNode& n : mesh.nodes) out << fmt::format("{:.9g} {:.9g} {:.9g}\n", n.reference.position.x(), n.reference.position.y(), n.reference.position.z());
  out << "</DataArray>\n</Points>\n<PointData Vectors=\"displacement\">\n";
  out << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < points; ++i) {
    const Vec3 u = displacement(analysis, static_cast<int>(i));
    out << fmt::format("{:.9g} {:.9g} {:.9g}\n", u.x(), u.y(), u.z());
  }
  out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"rotation_vector\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < points; ++i) {
    const Vec3 r = rotation(analysis, static_cast<int>(i));
    out << fmt::format("{:.9g} {:.9g} {:.9g}\n", r.x(), r.y(), r.z());
  }
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"wire\" format=\"ascii\">\n";
  for (const MeshNode& n : mesh.nodes) out << n.wire << "\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"layer\" format=\"ascii\">\n";
  for (const MeshNode& n : mesh.nodes) out << n.layer << "\n";
  out << "</DataArray>\n</PointData>\n<CellData>\n";
  // Each quadratic element is written as two straight cells carrying its two integration points' results.
  const char* names[6] = {"axial_force_N", "shear_force_2_N", "shear_force_3_N", "torsion_Nmm", "bending_moment_2_Nmm", "bending_moment_3_Nmm"};
  for (int c = 0; c < 6; ++c) {
    out << "<DataArray type=\"Float64\" Name=\"" << names[c] << "\" format=\"ascii\">\n";
    for (const BeamElementState& e : analysis.model_state().elements)
      out << fmt::format("{:.9g}\n{:.9g}\n", e.points[0].resultants[c], e.points[1].resultants[c]);
    out << "</DataArray>\n";
  }
  out << "<DataArray type=\"Float64\" Name=\"axial_strain\" format=\"ascii\">\n";
  for (const BeamElementState& e : analysis.model_state().elements)
    out << fmt::format("{:.9g}\n{:.9g}\n", e.points[0].strain[0], e.points[1].strain[0]);
  out << "</DataArray>\n";
  // Section-point fields reduced per element (both cells of an element carry its values).
  const std::vector<ElementResult> reduced = element_results(model, analysis.model_state());
  const std::array<std::pair<const char*, double ElementResult::*>, 4> fields = {{
      {"von_mises_max_MPa", &ElementResult::max_von_mises},
      {"von_mises_mean_MPa", &ElementResult::mean_von_mises},
      {"plastic_strain_max", &ElementResult::max_plastic_strain},
      {"plastic_strain_mean", &ElementResult::mean_plastic_strain}}};
  for (const auto& [field_name, member] : fields) {
    out << "<DataArray type=\"Float64\" Name=\"" << field_name << "\" format=\"ascii\">\n";
    for (const ElementResult& r : reduced) out << fmt::format("{:.7g}\n{:.7g}\n", r.*member, r.*member);
    out << "</DataArray>\n";
  }
  out << "</CellData>\n<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const MeshElement& e : mesh.elements) out << e.nodes[0] << " " << e.nodes[1] << "\n" << e.nodes[1] << " " << e.nodes[2] << "\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 1; i <= cells; ++i) out << 2 * i << "\n";
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < cells; ++i) out << "3\n";  // VTK_LINE
  out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  file.commit();
  contacts_.write_vtu(analysis, fmt::format("contacts_{:05d}.vtu", frames_.size()), time);
  frames_.emplace_back(time, name);
  write_pvd();
}

void ResultWriter::write_pvd() const {
  WholeFile file(directory_ / "result.pvd");
  std::ostream& out = file.stream();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [time, file] : frames_)
    out << "<DataSet timestep=\"" << fmt::format("{:.9g}", time) << "\" file=\"" << file << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  file.commit();
}

void ResultWriter::finish(const StaticAnalysis& analysis, const AnalysisStatus& status, double wall_seconds) {
  if (case_.output.vtu && !last_written_ && increments_seen_ > 0)
    write_vtu(analysis, rows_.empty() ? 0.0 : rows_.back().load_factor);
  WholeFile displacements(directory_ / "displacements.csv");
  std::ostream& d = displacements.stream();
  d << "node,wire,layer,x0,y0,z0,ux,uy,uz,rx,ry,rz\n";
  const Mesh& mesh = analysis.model().mesh;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const MeshNode& n = mesh.nodes[i];
    const Vec3 u = displacement(analysis, static_cast<int>(i)), r = rotation(analysis, static_cast<int>(i));
    d << fmt::format("{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", i, n.wire,
                     n.layer, n.reference.position.x(), n.reference.position.y(), n.reference.position.z(), u.x(), u.y(),
                     u.z(), r.x(), r.y(), r.z());
  }
  displacements.commit();
  nlohmann::json summary = run_summary(analysis, wall_seconds);
  summary["status"] = status.converged ? "converged" : "not_converged";
  if (!status.converged) summary["message"] = status.message;
  write_summary(summary);
}

}  // namespace strandfem
