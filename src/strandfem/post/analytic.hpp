// Closed-form strand references: bending stiffness bounds (EImax, EImin) and linear axial-torsional stiffness.
#pragma once
#include <vector>

#include "strandfem/geometry/strand.hpp"

namespace strandfem {

// Papailiou's bounds (1997), as used by the paper (eqs. 1.1, 1.2), summed over layers (core: alpha = 0, R = 0):
//   EImin = sum n E I0 cos(alpha),  EImax = EImin + sum 1/2 n E A R^2 cos^3(alpha).   [N mm^2]
// With them, the wires' transverse shear stiffness for the Timoshenko form of eq. 3.2 (tensioned_timoshenko_deflection):
//   S = sum n kappa G A cos(alpha), kappa = 6 (1 + nu) / (7 + 6 nu) as in the elements' sections (Cowper).  [N]
struct BendingStiffnessBounds {
  double ei_min = 0;
  double ei_max = 0;
  double wire_shear_stiffness = 0;
};
BendingStiffnessBounds bending_stiffness_bounds(const StrandSpec& strand);

// Linearised thin-rod strand theory in the form of Costello (Theory of Wire Rope, 1997, ch. 3), derived
// by linearising the Love rod equations of each helical wire about the straight-strand helix:
//   F = C11 eps + C12 tau,   M = C21 eps + C22 tau
// eps: strand axial strain, tau: strand twist per unit length (rad/mm, positive in the lay direction of
// the outer layer), F in N, M in N mm. Assumptions: wires are thin elastic rods whose centerlines stay on
// cylinders of fixed radius (no Poisson contraction, no contact flattening, no friction); the wire twist
// follows the helix torsion; all wires of a layer share the load equally; the core sees eps and tau only.
// Fixed ends (tau = 0): k_fixed = C11. Free ends (M = 0): k_free = C11 - C12 C21 / C22, with the end
// rotating by tau = -C21/C22 eps per unit length.
struct LinearStrandStiffness {
  double c11 = 0, c12 = 0, c21 = 0, c22 = 0;
  double axial_fixed() const { return c11; }
  double axial_free() const { return c11 - c12 * c21 / c22; }
  double twist_per_strain_free() const { return -c21 / c22; }
};
LinearStrandStiffness linear_strand_stiffness(const StrandSpec& strand);

struct StrandProperties {
  double metallic_area = 0;    // mm^2, sum of wire cross-sections
  double mass_per_length = 0;  // kg/m
  double axial_stiffness_sum = 0;  // N, sum of E A over all wires (no lay-angle reduction)
};
StrandProperties strand_properties(const StrandSpec& strand);

// Radial (crossing) contacts between layer `layer` and layer `layer - 1` over the strand length predicted by
// the paper's eq. 2.4: along a wire of layer i, crossings with layer i-1 recur every
// x = 2 pi R_ct cos(a_{i-1}) / (n_{i-1} sin(a_i + a_{i-1})), R_ct = R_i - d_i / 2 (opposite lay directions).
// Returns n_i L / (x cos a_i); requires layer >= 2 (the core has no crossings).
double radial_contact_count_eq24(const StrandSpec& strand, int layer);

// The same count from the helices' actual angular rates tan(a)/R at their own layer radii (eq. 2.4 puts
// both helices on R_ct): n_i n_{i-1} L |tan a_i / R_i - s tan a_{i-1} / R_{i-1}| / (2 pi), s = +1 for the
// same lay direction, -1 for opposite.
double radial_contact_count_helix(const StrandSpec& strand, int layer);

// Poffenberger and Swart (1965), as the EPRI Orange Book writes it: the stress amplitude (MPa) of an outer wire at
// the last point of contact of a clamp, for a peak-to-peak bending amplitude `yb` (mm) measured `xb` (mm) from that
// point, of a conductor under `tension` (N) taken as a beam of stiffness `ei_min` (N mm²), the wire of modulus
// `wire_modulus` (MPa) and diameter `wire_diameter` (mm): sigma_a = K yb, K = E d p² / (4 (e^(-p xb) - 1 + p xb)),
// p = sqrt(T / EImin). Without tension, K = E d / (2 xb²).
double poffenberger_swart_stress(double yb, double tension, double ei_min, double wire_modulus, double wire_diameter, double xb);
constexpr double kPoffenbergerSwartDistance = 89.0;  // mm from the last point of contact (IEEE / CIGRE convention)

}  // namespace strandfem
