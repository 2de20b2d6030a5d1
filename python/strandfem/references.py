"""Closed-form references in the paper's units (N, mm; EI in N mm^2): the tensioned clamped beam of eqs. 3.1 and
3.2 and the bending stiffness it implies. The strand's own EImax, EImin and linear axial stiffness come with a case:
Case.references()."""
import numpy as np

from strandfem import _core


def midspan_deflection(load, tension, bending_stiffness, span):
    """Eq. 3.1: midspan deflection (mm) of a beam clamped at both ends, span L, under tension T and a transverse
    load V at midspan: y = V/T (L/4 - k tanh(L/(4k))), k = sqrt(EI/T)."""
    return np.vectorize(_core.tensioned_beam_midspan_deflection)(load, tension, bending_stiffness, span)[()]


def deflection_curve(load, tension, bending_stiffness, span, x):
    """Eq. 3.2: the same beam's deflection (mm) at x mm from a clamp (0 <= x <= L/2; symmetric about midspan)."""
    return np.vectorize(_core.tensioned_beam_deflection)(load, tension, bending_stiffness, span, x)[()]


def deflection_curve_with_shear(load, tension, bending_stiffness, shear_stiffness, span, x):
    """Eq. 3.2 with the wires' shear flexibility (Timoshenko, shear stiffness S in N), as the bounds of the
    bending results use for EImin."""
    return np.vectorize(_core.tensioned_timoshenko_deflection)(load, tension, bending_stiffness, shear_stiffness, span, x)[()]


def equivalent_bending_stiffness(compliance, tension, span):
    """The EI (N mm^2) for which eq. 3.1 gives the midspan compliance y/V (mm/N) under tension T: a measured
    deflection's secant EI. 0 at the string's compliance L/(4T), infinity at or below zero."""
    return np.vectorize(_core.equivalent_bending_stiffness)(compliance, tension, span)[()]


def poffenberger_swart_stress(yb, tension, ei_min, wire_modulus, wire_diameter, xb=89.0):
    """Poffenberger and Swart (1965): the stress amplitude (MPa) of an outer wire (modulus E in MPa, diameter d in
    mm) for a peak-to-peak bending amplitude yb (mm) at xb mm from a clamp's last point of contact, the conductor a
    beam of EImin (N mm^2) under the tension T (N): yb E d p^2 / (4 (exp(-p xb) - 1 + p xb)), p = sqrt(T/EImin)."""
    return np.vectorize(_core.poffenberger_swart_stress)(yb, tension, ei_min, wire_modulus, wire_diameter, xb)[()]
