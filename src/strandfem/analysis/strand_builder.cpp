#include "strandfem/analysis/strand_builder.hpp"

#include <cmath>

namespace strandfem {

StrandModelParts build_strand_model(const StrandSpec& strand, const MeshSpec& mesh_spec, bool free_ends) {
  StrandModelParts s;
  s.mesh = mesh_strand(strand, mesh_spec);
  const Mesh& m = s.mesh;
  const MeshWire& core = m.wires[0];
  s.start_node = core.nodes.front();
  s.end_node = core.nodes.back();
  s.monitor_node = core.nodes[core.nodes.size() / 2];
  for (std::size_t w = 1; w < m.wires.size(); ++w) {
    for (const int end : {0, 1}) {
      const int slave = end == 0 ? m.wires[w].nodes.front() : m.wires[w].nodes.back();
      const int master = end == 0 ? s.start_node : s.end_node;
      s.ties.push_back(make_rigid_tie(slave, master, m.nodes[slave].reference, m.nodes[master].reference));
    }
  }
  const Support clamp{s.start_node, {true, true, true, true, true, true}};
  const Support far{s.end_node, {true, true, false, true, true, !free_ends}};
  s.supports = {clamp, far};
  return s;
}

void add_rigid_section(const Mesh& m, int core_node, std::vector<RigidTie>& ties) {
  const double z = m.nodes[core_node].reference.position.z();
  for (std::size_t w = 1; w < m.wires.size(); ++w) {
    int nearest = m.wires[w].nodes.front();
    for (const int n : m.wires[w].nodes)
      if (std::abs(m.nodes[n].reference.position.z() - z) < std::abs(m.nodes[nearest].reference.position.z() - z)) nearest = n;
    bool tied = false;
    for (const RigidTie& t : ties) tied |= t.slave == nearest;
    if (!tied) ties.push_back(make_rigid_tie(nearest, core_node, m.nodes[nearest].reference, m.nodes[core_node].reference));
  }
}

void add_rigid_block(const Mesh& m, int master, double z_min, double z_max, std::vector<RigidTie>& ties) {
  std::vector<char> taken(m.nodes.size(), 0);
  taken[master] = 1;
  for (const RigidTie& t : ties) taken[t.slave] = taken[t.master] = 1;
  for (const MeshWire& wire : m.wires)
    for (const int n : wire.nodes) {
      const double z = m.nodes[n].reference.position.z();
      if (taken[n] || z < z_min || z > z_max) continue;
      ties.push_back(make_rigid_tie(n, master, m.nodes[n].reference, m.nodes[master].reference));
      taken[n] = 1;
    }
}

NodalAction axial_strain_action(const StrandModelParts& s, double axial_strain, double length) {
  return {NodalAction::kMotion, s.end_node, kUz, axial_strain * length};
}
NodalAction axial_force_action(const StrandModelParts& s, double axial_force) {
  return {NodalAction::kForce, s.end_node, kUz, axial_force};
}
NodalAction torque_action(const StrandModelParts& s, double torque) { return {NodalAction::kForce, s.end_node, kRz, torque}; }
NodalAction twist_action(const StrandModelParts& s, double twist_radians) {
  return {NodalAction::kMotion, s.end_node, kRz, twist_radians};
}

std::vector<NodalAction> transverse_actions(const TransverseLoad& load) {
  std::vector<NodalAction> out;
  for (int c = 0; c < 2; ++c)
    if (load.direction[c] != 0) out.push_back({NodalAction::kForce, load.node, c, load.value * load.direction[c]});
  return out;
}

}  // namespace strandfem
