// A strand model built from plain data (analysis/strand_builder): end planes, supports and load actions.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "strandfem/analysis/strand_builder.hpp"

namespace strandfem {
namespace {

StrandSpec seven_wire(double length) {
  StrandSpec s;
  s.length = length;
  s.materials["steel"] = Material{188000, 0.3, 7.85e-9, "steel", {}};
  s.layers.push_back(LayerSpec{1, 3.94, "steel"});
  LayerSpec outer{6, 3.73, "steel", 11.8 * M_PI / 180};
  s.layers.push_back(outer);
  return s;
}

TEST(StrandBuilder, EndPlanesTieEveryWireToTheCoreEnds) {
  const StrandModelParts s = build_strand_model(seven_wire(60), MeshSpec{10.0, 0}, false);
  ASSERT_EQ(s.mesh.wires.size(), 7u);
  EXPECT_EQ(s.start_node, s.mesh.wires[0].nodes.front());
  EXPECT_EQ(s.end_node, s.mesh.wires[0].nodes.back());
  EXPECT_NEAR(s.mesh.nodes[s.monitor_node].reference.position.z(), 30.0, 1e-9);
  ASSERT_EQ(s.ties.size(), 12u);
  std::set<int> slaves;
  for (const RigidTie& t : s.ties) {
    slaves.insert(t.slave);
    const double z_slave = s.mesh.nodes[t.slave].reference.position.z(), z_master = s.mesh.nodes[t.master].reference.position.z();
    EXPECT_NEAR(z_slave, z_master, 1e-9);  // each end plane ties its own end
    EXPECT_TRUE(t.master == s.start_node || t.master == s.end_node);
  }
  EXPECT_EQ(slaves.size(), 12u);
  // Clamped at z = 0; at z = L the axial motion is free and, with fixed ends, the twist held.
  ASSERT_EQ(s.supports.size(), 2u);
  for (int c = 0; c < 6; ++c) EXPECT_TRUE(s.supports[0].fixed[c]);
  EXPECT_FALSE(s.supports[1].fixed[kUz]);
  EXPECT_TRUE(s.supports[1].fixed[kRz]);
  EXPECT_FALSE(build_strand_model(seven_wire(60), MeshSpec{10.0, 0}, true).supports[1].fixed[kRz]);
}

TEST(StrandBuilder, LoadsBecomeActionsOnTheirNodes) {
  StrandModelParts s = build_strand_model(seven_wire(60), MeshSpec{10.0, 0}, true);
  const NodalAction strain = axial_strain_action(s, 0.002, 60);
  EXPECT_EQ(strain.kind, NodalAction::kMotion);
  EXPECT_EQ(strain.node, s.end_node);
  EXPECT_EQ(strain.component, kUz);
  EXPECT_DOUBLE_EQ(strain.value, 0.12);
  EXPECT_EQ(axial_force_action(s, 5000).kind, NodalAction::kForce);
  EXPECT_EQ(twist_action(s, 0.1).component, kRz);
  EXPECT_EQ(torque_action(s, 2.0).value, 2.0);
  const auto along_y = transverse_actions({s.monitor_node, 100.0, Vec3::UnitY()});
  ASSERT_EQ(along_y.size(), 1u);
  EXPECT_EQ(along_y[0].component, kUy);
  const auto oblique = transverse_actions({s.monitor_node, 100.0, Vec3(0.6, 0.8, 0)});
  ASSERT_EQ(oblique.size(), 2u);
  EXPECT_DOUBLE_EQ(oblique[0].value, 60.0);
  EXPECT_DOUBLE_EQ(oblique[1].value, 80.0);
  // A loading clamp ties one node of every other wire at the core node's z, once.
  add_rigid_section(s.mesh, s.monitor_node, s.ties);
  ASSERT_EQ(s.ties.size(), 18u);
  for (std::size_t k = 12; k < 18; ++k) {
    EXPECT_EQ(s.ties[k].master, s.monitor_node);
    EXPECT_NEAR(s.mesh.nodes[s.ties[k].slave].reference.position.z(), 30.0, 3.0);
  }
  add_rigid_section(s.mesh, s.monitor_node, s.ties);
  EXPECT_EQ(s.ties.size(), 18u);
}

}  // namespace
}  // namespace strandfem
