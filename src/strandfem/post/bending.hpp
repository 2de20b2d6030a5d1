// Bending under tension: closed-form deflections of a tensioned beam (paper eqs. 3.1, 3.2) and the
// hysteresis loops of a cyclic load-deflection history.
#pragma once
#include <vector>

namespace strandfem {

// A beam of bending stiffness EI (N mm^2) under tension T (N), clamped at both ends (no rotation, span L in
// mm) with a transverse load V (N) at midspan; k = sqrt(EI / T). Deflection at distance x from a clamp
// (0 <= x <= L/2; the curve is symmetric), eq. 3.2 with s = L/4:
//   y(x) = V k / (2T) [x/k - sinh(x/k) + tanh(s/k) (cosh(x/k) - 1)].
// It tends to the Euler-Bernoulli V x^2 (3L - 4x) / (48 EI) as T -> 0 and to the string V x / (2T) as EI -> 0.
double tensioned_beam_deflection(double load, double tension, double bending_stiffness, double span, double x);

// The same beam with the shear flexibility of Timoshenko's theory, shear stiffness S = kappa G A (N, S > T), the
// axial force acting along the section normal as in the beam elements. With the section rotation theta held at
// both clamps and at midspan, EI theta'' - T (1 - T/S) theta = -V/2 (1 - T/S) gives
//   y(x) = (1 - T/S)^2 y_3.2(x; EI, T (1 - T/S)) + V x / (2S),
// which is eq. 3.2 as S -> infinity and V x^2 (3L - 4x) / (48 EI) + V x / (2S) as T -> 0.
double tensioned_timoshenko_deflection(double load, double tension, double bending_stiffness, double shear_stiffness,
                                       double span, double x);

// Midspan value of the same curve (eq. 3.1): y_max = V/T (L/4 - k tanh(L / (4k))).
double tensioned_beam_midspan_deflection(double load, double tension, double bending_stiffness, double span);

// The bending stiffness EI for which eq. 3.1 gives midspan compliance y/V = compliance (mm/N) under tension
// T: 0 when the compliance reaches the string's L/(4T), infinity when it is <= 0.
double equivalent_bending_stiffness(double compliance, double tension, double span);

// One core node of a deflection curve at a peak load beside eq. 3.2's bounds: x (mm) from the nearer clamp, the
// node's deflection, the EImax curve (the stiffest strand, below) and the larger of the EImin curves with and
// without the wires' shear (the softest, above).
struct CurveSample {
  double x = 0;
  double deflection = 0;
  double lower_bound = 0;
  double upper_bound = 0;
};

// How a deflection curve lies between its bounds over the nodes at x >= from_clamp (and x > 0: the clamped
// end nodes, where every curve is 0, are left out).
struct CurveBoundsCheck {
  int nodes = 0;                  // nodes checked
  int within = 0;                 // of them, lower_bound <= deflection <= upper_bound
  double largest_excess = 0;      // mm above the upper bound (0: none above)
  double largest_excess_x = 0;    // where, mm from the nearer clamp
  double largest_excess_relative = 0;  // that excess over the upper bound there
  double largest_shortfall = 0;   // mm below the lower bound (0: none below)
  double largest_shortfall_x = 0;
};
CurveBoundsCheck check_curve_bounds(const std::vector<CurveSample>& curve, double from_clamp = 0);

// A point of the core's deflection curve: reference z (mm) and deflection (mm).
struct DeflectionPoint {
  double z = 0;
  double deflection = 0;
};

// The rise of a deflection curve over `distance` mm from the load point, as the paper's Figs. 8, 9a and 15a draw
// it: the deflection at load_z minus the mean of the deflections at load_z -/+ distance, linear between points
// (sorted by z); a side beyond the curve's ends takes the end point.
double rise_from_load_point(const std::vector<DeflectionPoint>& curve, double load_z, double distance);

// One converged state of a cyclic transverse load: load V and midspan deflection y.
struct LoadDeflectionPoint {
  int cycle = 0;          // 1-based cycle of the load protocol
  bool returning = false; // on the half that brings V back
  double load = 0;        // N
  double deflection = 0;  // mm
  double tension = 0;     // N, axial force of the strand
  double friction_dissipation = 0;  // N mm: work of friction at every contact since the start of the run
};

// A cycle's loop: from the state before the cycle, out to the peak load and back.
struct HysteresisLoop {
  int cycle = 0;
  // N mm: work of V over the cycle (polygon closed by a straight line). It is the friction dissipation plus the
  // elastic energy the cycle leaves locked in by friction (its set): the two agree once the loop is steady.
  double area = 0;
  double friction_dissipation = 0;  // N mm: work of friction at every contact over the cycle
  double peak_load = 0;           // V at the turning point
  double peak_deflection = 0;     // y there
  double peak_tension = 0;        // axial force there
  double start_deflection = 0;    // y where the cycle started
  double end_deflection = 0;      // y where it ended (ratchet: end - start)
  double secant_stiffness = 0;    // (V_peak - V_start) / (y_peak - y_start), N/mm
  double loading_tangent = 0;     // dV/dy over the first increment out, N/mm
  double unloading_tangent = 0;   // dV/dy over the first increment back, N/mm
  // The loop as the paper draws its Cardinal loops (Fig. 9b: "the first transversal load application" removed): the
  // previous cycle's return half and this cycle's loading half, from peak to peak (polygon closed by a straight
  // line between the two peaks). It leaves out the set that a first loading locks in, which `area` carries.
  // Only for a cycle that starts where the previous one ended; has_return_loop is false otherwise (cycle 1).
  bool has_return_loop = false;
  double return_loop_area = 0;                  // N mm
  double return_loop_friction_dissipation = 0;  // N mm: work of friction from the previous peak to this one
};

// Loops of every complete cycle in the history (points in load order; the point before a cycle's first
// increment, e.g. the end of the tension ramp, is the cycle's start), each with its return loop from cycle 2 on.
std::vector<HysteresisLoop> hysteresis_loops(const std::vector<LoadDeflectionPoint>& history);

// How cycle n differs from cycle n - 1, relative: the area and friction's work against the larger of the two, the
// peak deflection against the larger deflection range (peak - start) of the two cycles. Signed: n - (n - 1).
struct CycleChange {
  double area = 0;
  double friction_dissipation = 0;
  double peak_deflection = 0;
};
CycleChange cycle_change(const HysteresisLoop& previous, const HysteresisLoop& current);

// Whether cycle n repeats cycle n - 1: its area and peak deflection changes (cycle_change) within the tolerance.
bool loop_is_steady(const HysteresisLoop& previous, const HysteresisLoop& current, double tolerance);

}  // namespace strandfem
