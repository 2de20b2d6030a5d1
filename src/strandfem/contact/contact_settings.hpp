// Contact options: penalty factors (paper eqs. 2.5-2.6), friction per material pair and axial zone, search.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "strandfem/core/types.hpp"

namespace strandfem {

// The paper's two kinds of wire contact (section 2.2, Fig. 2): lateral between wires of one layer and between the
// core and the first layer, radial between wires of two adjacent helical layers.
enum class ContactInterface { kLateral, kRadial };
const char* to_string(ContactInterface interface);
// The interface of a contact between wires of layers layer_a and layer_b (0 = core).
ContactInterface contact_interface(int layer_a, int layer_b);

// Friction for one pair of materials (order does not matter), optionally only on one interface.
struct MaterialPairFriction {
  std::string material_a, material_b;
  // none: the entry sets only the ratio, the coefficient comes from the next rule (contact.friction).
  std::optional<double> coefficient;
  // mu2 / mu1 for this pair; none: the contact's orthotropy_ratio. The paper's Fig. 19 makes the aluminum contacts
  // orthotropic and keeps steel-steel and steel-aluminum at their isotropic 0.3 and 0.5.
  std::optional<double> orthotropy_ratio;
  // none: lateral and radial contacts alike.
  std::optional<ContactInterface> interface;
  bool applies_to(const std::string& a, const std::string& b, ContactInterface on) const;
};

// Friction coefficient on an axial band z_min <= z <= z_max (multi-level model, paper section 5.2).
// Zones override material pairs; the first zone containing the contact wins.
struct FrictionZone {
  double z_min = 0, z_max = 0;
  double coefficient = 0;
  // Material pairs the zone applies to (the paper's section 5.2 changes aluminum contacts only); empty: all.
  std::vector<std::pair<std::string, std::string>> material_pairs;
  // none: lateral and radial contacts alike (section 5.2 changes the radial ones only).
  std::optional<ContactInterface> interface;
  bool applies_to(const std::string& material_a, const std::string& material_b, ContactInterface on) const;
};

// What to do with overlaps present in the nominal (reference) geometry.
enum class InitialOverlap {
  kOffset,  // subtract each contact point's reference overlap (or near-touch gap) from its gap: stress-free start
  kKeep     // keep it: the overlap is pressed out in the first increment
};

// What friction direction 1 of an orthotropic contact follows (section 5.3).
enum class FrictionDirection { kStrandAxis, kSlaveWire };
const char* to_string(FrictionDirection direction);

// How the tangential (stick) penalty is set.
enum class TangentialPenalty {
  kPaper,       // eq. 2.6: K_t = fKt mu E d^2 xi_t / h, fixed
  kElasticSlip  // from an allowed elastic slip: K_t = mu P / (elastic_slip h), P the current normal force
};

// The default normal onset width per diameter of the thinner wire: a band where the answer no longer moves
// (docs/validation/regularization.md, "The normal onset").
constexpr double kNormalOnsetPerDiameter = 1e-5;

struct ContactSettings {
  bool enabled = false;
  // Penalty factors of eqs. 2.5-2.6: K_n = fKn E d xi_n and K_t = fKt mu E d^2 xi_t / h (N/mm, point
  // contacts); line contacts use the same divided by d (N/mm^2, i.e. force per length per mm of gap).
  double normal_factor = 1.0;           // fKn
  double tangential_factor = 50.0;      // fKt
  double normal_multiplier = 10.0;      // xi_n
  double tangential_multiplier = 3.75;  // xi_t
  TangentialPenalty tangential_penalty = TangentialPenalty::kElasticSlip;
  // kElasticSlip: allowed elastic slip as a fraction of the contact element length h. A tenth of Abaqus' 0.005:
  // bending moves crossings by hundredths of a millimetre, and 0.05 mm of elastic slip (10 mm elements) let them
  // all stick elastically (docs/validation/regularization.md, "The stick's elastic slip in bending").
  double elastic_slip = 0.0005;
  // Augmented stick (Uzawa on the tangential penalty): once Newton has converged, each sticking point's force takes
  // over its elastic slip and Newton goes on, until no sticking point has slipped elastically by more than
  // stick_tolerance x its allowed slip or stick_augmentations rounds are spent. The stick then tends to Coulomb's
  // (no relative motion) while the penalty, and with it Newton's conditioning, stays; 0: the penalty stick alone.
  // The analysis also ends the rounds once one barely moves the nodes and the loads.
  int stick_augmentations = 0;
  double stick_tolerance = 0.05;
  // Friction: default coefficient, then material pairs, then axial zones (highest priority).
  double friction = 0.0;
  std::vector<MaterialPairFriction> pair_friction;
  std::vector<FrictionZone> zone_friction;
  double orthotropy_ratio = 1.0;  // mu2 / mu1 (mu1 along friction direction 1)
  Vec3 strand_axis = Vec3::UnitZ();
  // Friction direction 1 of orthotropic points, projected on the contact plane: the strand axis (section 5.3's
  // text), or the slave wire's tangent (the x axis of the paper's CONTA176 elements, mapped onto the inner wire
  // at crossings).
  FrictionDirection friction_direction = FrictionDirection::kStrandAxis;
  // Search: element boxes are inflated by the wire radius plus this margin (mm); the search reruns when a
  // node has moved more than half the margin since the last search.
  double search_margin = 0.5;
  // Tangent pattern: a candidate's element pair enters the pattern once one of its points is closed or open by
  // less than this fraction of r_a + r_b (leaving again beyond twice that); pairs of candidates held
  // apart (the lay gaps between wires of one layer) stay out, which divides the factorization's flops by up
  // to six. A point that closes outside the pattern widens it at once (re-analysis). 0.003 rather than 0.01
  // S32 under bending keeps lay gaps of 0.01-0.035 mm out, 21 % fewer factor entries.
  double pattern_margin = 0.003;
  // Centerlines closer than this angle (degrees) are in line contact, others in point contact.
  double line_contact_angle = 20.0;
  int line_points = 4;  // Gauss points per slave element for line contacts
  InitialOverlap initial_overlap = InitialOverlap::kOffset;
  // With kOffset, reference gaps below this fraction of r_a + r_b are offset too (not only overlaps):
  // the quadratic interpolation of a helix leaves gaps of order 1e-4 mm between wires meant to touch, and
  // the nominal layer radii leave crossing gaps of a few 1e-2 mm on which outer wires would float.
  double touch_tolerance = 0.02;
  // Width (mm) of the gap band |g| < s over which the normal force sets in smoothly (C1, quadratic), so that
  // contacts near zero force do not switch one by one; none: kNormalOnsetPerDiameter x the thinner wire's
  // diameter; 0: the plain penalty law with the active set.
  std::optional<double> normal_smoothing;
  // Contact stabilization: a tangential spring of this fraction of the normal penalty at every contact point,
  // anchored where the point was at the last converged increment, so that it resists only the motion within an
  // increment (a damper in load time). Wires whose contacts slide freely (no friction, or eq. 2.6's sliding
  // points) shift sideways held only by their tension, and Newton's corrections wander along those modes; 0: none.
  double stabilization = 0.0;

  // Throws std::invalid_argument naming the contact.* key that is wrong.
  void validate() const;
  // Coefficient for the materials of the two wires on the given interface at axial position z: the first zone
  // that applies, else the first friction_pairs entry that applies and sets mu, else friction.
  double friction_at(const std::string& material_a, const std::string& material_b, ContactInterface on, double z) const;
  // The same outside every zone.
  double friction_outside_zones(const std::string& material_a, const std::string& material_b, ContactInterface on) const;
  // mu2 / mu1: the first friction_pairs entry that applies and sets a ratio, else orthotropy_ratio.
  double orthotropy_at(const std::string& material_a, const std::string& material_b, ContactInterface on) const;
};

// Penalty stiffnesses of a contact point (eqs. 2.5-2.6).
struct PenaltyStiffness {
  double normal = 0;      // N/mm (point) or N/mm^2 (line)
  double tangential = 0;  // same units
  double smoothing = 0;   // mm: width over which the normal force sets in (0: the plain penalty law)
};

// youngs_modulus and diameter: the softer material and the thinner wire of the pair; element_size: h,
// the slave element's length.
PenaltyStiffness penalty_stiffness(const ContactSettings& settings, bool line_contact, double youngs_modulus,
                                   double diameter, double element_size, double friction);

}  // namespace strandfem
