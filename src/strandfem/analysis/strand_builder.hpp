// Builds a strand model from plain data, without a case file: the wires' mesh, the rigid end planes and the
// supports of paper section 2.4, and the nodal actions that the strand's loads (axial strain or force, torque
// or twist, a transverse load at a position) stand for.
#pragma once
#include <vector>

#include "strandfem/analysis/load_protocol.hpp"
#include "strandfem/constraints/rigid_tie.hpp"
#include "strandfem/geometry/strand.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

// What a strand model is made of before any load: its mesh, end-plane ties and supports, and the core nodes
// the results probe.
struct StrandModelParts {
  Mesh mesh;
  std::vector<RigidTie> ties;
  std::vector<Support> supports;
  int start_node = -1;    // core node at z = 0 (clamped)
  int end_node = -1;      // core node at z = L (loaded)
  int monitor_node = -1;  // core node nearest mid-length
};

// Meshes the strand and ties every wire's end nodes to the core end nodes (rigid end planes). The end at z = 0
// is clamped; the end at z = L keeps its axial displacement free, and with free_ends its twist too. Throws
// ModelSizeError beyond the model-size limit.
StrandModelParts build_strand_model(const StrandSpec& strand, const MeshSpec& mesh, bool free_ends);

// Ties the node nearest the core node's z on every other wire rigidly to that core node (a loading clamp);
// wires whose node there is already tied keep their tie.
void add_rigid_section(const Mesh& mesh, int core_node, std::vector<RigidTie>& ties);

// Ties every node of every wire with reference z in [z_min, z_max] rigidly to `master` (a saddle or a clamp
// holding the strand over a length); nodes already tied, and masters of other ties, keep their role.
void add_rigid_block(const Mesh& mesh, int master, double z_min, double z_max, std::vector<RigidTie>& ties);

// A transverse load on the strand: `value` N along `direction` (unit, perpendicular to z) at `node`.
struct TransverseLoad {
  int node = -1;
  double value = 0;
  Vec3 direction = Vec3::UnitY();
};

// Nodal actions of the strand's loads at the end node (z = L) and the transverse load's node.
NodalAction axial_strain_action(const StrandModelParts& strand, double axial_strain, double length);
NodalAction axial_force_action(const StrandModelParts& strand, double axial_force);
NodalAction torque_action(const StrandModelParts& strand, double torque);
NodalAction twist_action(const StrandModelParts& strand, double twist_radians);
std::vector<NodalAction> transverse_actions(const TransverseLoad& load);  // one per non-zero x, y component

}  // namespace strandfem
