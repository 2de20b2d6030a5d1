// Rigid-body tie of a slave node to a master node (rigid end planes of the strand, paper section 2.4).
#pragma once
#include "strandfem/beam/beam_element.hpp"
#include "strandfem/core/types.hpp"

namespace strandfem {

// x_s = x_m + Lambda_m Lambda_m0^T (X_s - X_m),  Lambda_s = Lambda_m Lambda_m0^T Lambda_s0 (exact, any rotation).
// The slave's DOFs are eliminated: a master increment (du_m, dtheta_m) moves the slave by
// du_s = du_m - (x_s - x_m)^ dtheta_m, dtheta_s = dtheta_m.
struct RigidTie {
  int slave = -1;
  int master = -1;
  Vec3 reference_arm = Vec3::Zero();                  // X_s - X_m in the master's reference frame axes
  Quaternion relative_rotation = Quaternion::Identity();  // Lambda_m0^T Lambda_s0
};

RigidTie make_rigid_tie(int slave, int master, const NodeState& slave_reference, const NodeState& master_reference);

// Slave state from the master state.
NodeState tied_state(const RigidTie& tie, const NodeState& master);

// 6x6 map T with d_slave = T d_master, for the current lever arm x_s - x_m.
Mat6 tie_transform(const Vec3& arm);

}  // namespace strandfem
