#include "strandfem/constraints/rigid_tie.hpp"

namespace strandfem {

RigidTie make_rigid_tie(int slave, int master, const NodeState& slave_reference, const NodeState& master_reference) {
  RigidTie t;
  t.slave = slave;
  t.master = master;
  t.reference_arm = master_reference.rotation.conjugate() * (slave_reference.position - master_reference.position);
  t.relative_rotation = master_reference.rotation.conjugate() * slave_reference.rotation;
  return t;
}

NodeState tied_state(const RigidTie& tie, const NodeState& master) {
  NodeState s;
  s.position = master.position + master.rotation * tie.reference_arm;
  s.rotation = (master.rotation * tie.relative_rotation).normalized();
  return s;
}

Mat6 tie_transform(const Vec3& arm) {
  Mat6 T = Mat6::Identity();
  T.block<3, 3>(0, 3) = -skew(arm);
  return T;
}

}  // namespace strandfem
