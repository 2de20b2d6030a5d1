#include "strandfem/contact/contact_settings.hpp"

#include <algorithm>
#include <stdexcept>

namespace strandfem {

namespace {
void require_positive(double v, const std::string& key) {
  if (!(v > 0)) throw std::invalid_argument("contact." + key + " must be > 0, got " + std::to_string(v));
}
void require_friction(double v, const std::string& key) {
  if (!(v >= 0 && v < 10)) throw std::invalid_argument("contact." + key + " must be a friction coefficient in [0, 10), got " + std::to_string(v));
}
}  // namespace

void ContactSettings::validate() const {
  require_positive(normal_factor, "normal_factor");
  require_positive(tangential_factor, "tangential_factor");
  require_positive(normal_multiplier, "normal_multiplier");
  require_positive(tangential_multiplier, "tangential_multiplier");
  require_friction(friction, "friction");
  for (const auto& p : pair_friction) {
    if (p.coefficient) require_friction(*p.coefficient, "friction_pairs[].mu");
    if (!p.coefficient && !p.orthotropy_ratio)
      throw std::invalid_argument("contact.friction_pairs[] must set mu, orthotropy_ratio or both");
    if (p.orthotropy_ratio) require_positive(*p.orthotropy_ratio, "friction_pairs[].orthotropy_ratio");
  }
  for (const auto& z : zone_friction) {
    require_friction(z.coefficient, "friction_zones[].mu");
    if (!(z.z_max > z.z_min)) throw std::invalid_argument("contact.friction_zones[].z must be [z_min, z_max] with z_max > z_min");
  }
  require_positive(orthotropy_ratio, "orthotropy_ratio");
  require_positive(elastic_slip, "elastic_slip");
  if (!(stabilization >= 0 && stabilization < 1))
    throw std::invalid_argument("contact.stabilization must be in [0, 1) (a fraction of the normal penalty), got " +
                                std::to_string(stabilization));
  if (normal_smoothing && !(*normal_smoothing >= 0)) throw std::invalid_argument("contact.normal_smoothing must be >= 0 (mm)");
  require_positive(search_margin, "search_margin");
  if (!(pattern_margin >= 0 && pattern_margin < 1)) throw std::invalid_argument("contact.pattern_margin must be in [0, 1)");
  if (!(touch_tolerance >= 0 && touch_tolerance < 0.5)) throw std::invalid_argument("contact.touch_tolerance must be in [0, 0.5)");
  if (!(line_contact_angle > 0 && line_contact_angle < 90))
    throw std::invalid_argument("contact.line_contact_angle must be in (0, 90) degrees, got " + std::to_string(line_contact_angle));
  if (line_points < 1 || line_points > 10) throw std::invalid_argument("contact.line_points must be in 1..10");
  if (!(strand_axis.norm() > 0)) throw std::invalid_argument("contact.axis must be a nonzero vector");
}

namespace {
bool same_pair(const std::string& a, const std::string& b, const std::string& material_a, const std::string& material_b) {
  return (a == material_a && b == material_b) || (a == material_b && b == material_a);
}
}  // namespace

const char* to_string(ContactInterface interface) { return interface == ContactInterface::kRadial ? "radial" : "lateral"; }
const char* to_string(FrictionDirection direction) {
  return direction == FrictionDirection::kSlaveWire ? "slave_wire" : "strand_axis";
}

ContactInterface contact_interface(int layer_a, int layer_b) {
  return layer_a != layer_b && std::min(layer_a, layer_b) >= 1 ? ContactInterface::kRadial : ContactInterface::kLateral;
}

bool MaterialPairFriction::applies_to(const std::string& a, const std::string& b, ContactInterface on) const {
  return same_pair(material_a, material_b, a, b) && (!interface || *interface == on);
}

bool FrictionZone::applies_to(const std::string& material_a, const std::string& material_b, ContactInterface on) const {
  if (interface && *interface != on) return false;
  if (material_pairs.empty()) return true;
  for (const auto& [a, b] : material_pairs)
    if (same_pair(a, b, material_a, material_b)) return true;
  return false;
}

double ContactSettings::friction_at(const std::string& material_a, const std::string& material_b, ContactInterface on,
                                    double z) const {
  for (const FrictionZone& zone : zone_friction)
    if (z >= zone.z_min && z <= zone.z_max && zone.applies_to(material_a, material_b, on)) return zone.coefficient;
  return friction_outside_zones(material_a, material_b, on);
}

double ContactSettings::friction_outside_zones(const std::string& material_a, const std::string& material_b,
                                               ContactInterface on) const {
  for (const MaterialPairFriction& p : pair_friction)
    if (p.coefficient && p.applies_to(material_a, material_b, on)) return *p.coefficient;
  return friction;
}

double ContactSettings::orthotropy_at(const std::string& material_a, const std::string& material_b, ContactInterface on) const {
  for (const MaterialPairFriction& p : pair_friction)
    if (p.orthotropy_ratio && p.applies_to(material_a, material_b, on)) return *p.orthotropy_ratio;
  return orthotropy_ratio;
}

PenaltyStiffness penalty_stiffness(const ContactSettings& s, bool line_contact, double youngs_modulus, double diameter,
                                   double element_size, double friction) {
  PenaltyStiffness k;
  k.normal = s.normal_factor * youngs_modulus * diameter * s.normal_multiplier;
  k.smoothing = s.normal_smoothing.value_or(kNormalOnsetPerDiameter * diameter);
  // mu = 0 would give no stick stiffness at all; frictionless contacts need none.
  k.tangential = s.tangential_factor * friction * youngs_modulus * diameter * diameter * s.tangential_multiplier / element_size;
  if (line_contact) {
    k.normal /= diameter;
    k.tangential /= diameter;
  }
  return k;
}

}  // namespace strandfem
