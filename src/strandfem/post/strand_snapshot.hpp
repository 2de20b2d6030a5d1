// A converged state of a strand reduced to what the bending results compare between load levels: the axial
// force at every wire node and the forces, slip and status of every contact point, at reference positions.
#pragma once
#include <vector>

#include "strandfem/solver/model_state.hpp"

namespace strandfem {

struct WireForceSample {
  int node = -1, wire = -1, layer = -1;
  double z = 0;              // reference axial position, mm
  double angle_degrees = 0;  // reference angular position about the strand axis, from x towards y
  double radius = 0;         // reference distance from the strand axis, mm (0 on the core)
  double axial_force = 0;    // N
};

// Contact point i of the model's contact set (the set only ever appends points, so i names the same point in
// every snapshot of a run). Line points carry forces per unit length (N/mm), crossings forces (N).
struct ContactSample {
  int kind = 0;              // ContactKind
  int layer_a = -1, layer_b = -1;
  double z = 0, angle_degrees = 0;  // reference position of the slave wire's centerline at the point
  double radius = 0;                // its distance from the strand axis, mm
  double normal_force = 0;          // P
  double tangential_force = 0;      // |Q|
  double slip = 0;                  // accumulated sliding, mm
  double dissipated_energy = 0;     // work of friction over that sliding, N mm (line points: over their length)
  // delta of the paper's Fig. 14: the sliding plus the elastic tangential displacement of the penalty spring
  // (|g_T|, the "relative sliding in stick conditions" of paper section 2.3), mm.
  double tangential_displacement = 0;
  int status = 0;                   // ContactStatus (a closed frictionless point reports stick)
  bool frictional = false;          // mu > 0: the point can stick
};

struct StrandSnapshot {
  std::vector<WireForceSample> wires;
  std::vector<ContactSample> contacts;
};

StrandSnapshot take_strand_snapshot(const Model& model, const ModelState& model_state);

// Statuses of the contact points now (ContactStatus as int), in point order.
std::vector<int> contact_statuses(const ModelState& model_state);

}  // namespace strandfem
