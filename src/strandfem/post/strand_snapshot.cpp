#include "strandfem/post/strand_snapshot.hpp"

#include <cmath>
#include <numbers>

#include "strandfem/contact/contact_kinematics.hpp"
#include "strandfem/post/wire_results.hpp"

namespace strandfem {

namespace {
double angle_of(const Vec3& x) {
  return std::hypot(x.x(), x.y()) > 1e-9 ? std::atan2(x.y(), x.x()) * 180.0 / std::numbers::pi : 0.0;
}
}  // namespace

StrandSnapshot take_strand_snapshot(const Model& model, const ModelState& model_state) {
  StrandSnapshot s;
  for (const WireNodeResult& r : wire_node_results(model, model_state))
    s.wires.push_back({r.node, r.wire, r.layer, r.z, r.angle_degrees, r.radius, r.resultants[0]});
  const ContactSet& contacts = model_state.contacts;
  const Mesh& mesh = model.mesh;
  s.contacts.reserve(contacts.points().size());
  for (std::size_t i = 0; i < contacts.points().size(); ++i) {
    const ContactPoint& p = contacts.points()[i];
    const ContactResponse& r = contacts.responses()[i];
    const MeshElement& e = mesh.elements[mesh.wires[p.wire_a].elements[p.element_a]];
    const double xi = p.kind == ContactKind::kLine ? p.xi : r.xi;
    const auto n = centerline_shape(xi);
    Vec3 x = Vec3::Zero();
    for (int k = 0; k < 3; ++k) x += n[k] * mesh.nodes[e.nodes[k]].reference.position;
    ContactSample c;
    c.kind = static_cast<int>(p.kind);
    c.layer_a = mesh.wires[p.wire_a].layer;
    c.layer_b = mesh.wires[p.wire_b].layer;
    c.z = x.z();
    c.angle_degrees = angle_of(x);
    c.radius = std::hypot(x.x(), x.y());
    c.status = static_cast<int>(r.status);
    c.frictional = p.mu1 > 0 || p.mu2 > 0;
    if (r.status != ContactStatus::kOpen) {
      c.normal_force = r.normal_force;
      c.tangential_force = std::hypot(r.q1, r.q2);
    }
    c.slip = p.history.slip;
    c.dissipated_energy = p.history.dissipated_energy;
    // After a commit the anchors of a sliding point sit on the friction cone, so |g_T| is the elastic part.
    c.tangential_displacement = c.slip + (r.status != ContactStatus::kOpen ? r.tangential_gap.norm() : 0.0);
    s.contacts.push_back(c);
  }
  return s;
}

std::vector<int> contact_statuses(const ModelState& model_state) {
  std::vector<int> out;
  out.reserve(model_state.contacts.responses().size());
  for (const ContactResponse& r : model_state.contacts.responses()) out.push_back(static_cast<int>(r.status));
  return out;
}

}  // namespace strandfem
