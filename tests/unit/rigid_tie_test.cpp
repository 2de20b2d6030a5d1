// Requirement: rigid end planes follow exact rigid-body kinematics under large rotations, and the
// linearised map T (d_slave = T d_master) is the derivative of that kinematics.
#include "strandfem/constraints/rigid_tie.hpp"

#include <gtest/gtest.h>

namespace strandfem {
namespace {

TEST(RigidTieTest, LargeRotationKeepsTheArmRigid) {
  NodeState master_ref, slave_ref;
  master_ref.position = Vec3(0, 0, 200);
  slave_ref.position = Vec3(3.835, 0.4, 200);
  slave_ref.rotation = Quaternion(Eigen::AngleAxisd(0.2, Vec3(0.3, 1, 0).normalized()));
  const RigidTie tie = make_rigid_tie(1, 0, slave_ref, master_ref);
  NodeState master;
  const Quaternion big(Eigen::AngleAxisd(2.5, Vec3(1, 2, 3).normalized()));  // 143 degrees
  master.position = Vec3(1, -2, 205);
  master.rotation = big;
  const NodeState slave = tied_state(tie, master);
  const Vec3 expected = master.position + big * (slave_ref.position - master_ref.position);
  EXPECT_LT((slave.position - expected).norm(), 1e-12);
  EXPECT_NEAR((slave.position - master.position).norm(), (slave_ref.position - master_ref.position).norm(), 1e-12);
  EXPECT_LT((slave.rotation.toRotationMatrix() - (big * slave_ref.rotation).toRotationMatrix()).norm(), 1e-12);
}

TEST(RigidTieTest, TransformIsDerivativeOfKinematics) {
  NodeState master_ref, slave_ref;
  slave_ref.position = Vec3(2, 1, 0);
  const RigidTie tie = make_rigid_tie(1, 0, slave_ref, master_ref);
  NodeState master;
  master.position = Vec3(0.3, 0.1, 4);
  master.rotation = Quaternion(Eigen::AngleAxisd(1.2, Vec3(0, 1, 1).normalized()));
  const NodeState slave = tied_state(tie, master);
  const Mat6 T = tie_transform(slave.position - master.position);
  const double h = 1e-7;
  for (int k = 0; k < 6; ++k) {
    NodeState plus = master, minus = master;
    if (k < 3) plus.position[k] += h, minus.position[k] -= h;
    else {
      plus.rotation = quaternion_from_rotation_vector(h * Vec3::Unit(k - 3)) * master.rotation;
      minus.rotation = quaternion_from_rotation_vector(-h * Vec3::Unit(k - 3)) * master.rotation;
    }
    const NodeState sp = tied_state(tie, plus), sm = tied_state(tie, minus);
    Vec6 d;
    d.head<3>() = (sp.position - sm.position) / (2 * h);
    d.tail<3>() = rotation_vector_from_quaternion(sp.rotation * sm.rotation.conjugate()) / (2 * h);
    EXPECT_LT((d - T.col(k)).norm(), 1e-6) << "master DOF " << k;
  }
}

}  // namespace
}  // namespace strandfem
