"""A friction study from Python (the paper's section 5.1 on a short strand): a 7-wire strand under 30 kN bent by
500 N at midspan and back, for three wire-to-wire friction coefficients. Prints each variant's peak deflection,
loop area and secant EI beside EImax and EImin and draws the loops.

    /usr/bin/python3 python/examples/friction_sweep.py OUT_DIR
"""
import os
import sys

import strandfem

STEEL = strandfem.Material("steel", E=188000, nu=0.3)
STRAND = strandfem.Strand(length=300, layers=[strandfem.Layer(1, 3.94, STEEL),
                                              strandfem.Layer(6, 3.73, STEEL, lay_angle=11.8)])
STEPS = [strandfem.Step("tension", 5, axial_force=30000),
         strandfem.Step("bend", 10, cycles=1, transverse_force={"value": 500, "z": 150, "direction": [0, 1, 0]})]

if __name__ == "__main__":  # the variants run in fresh interpreters, which import this file
    out = sys.argv[1] if len(sys.argv) > 1 else "friction_sweep"
    case = strandfem.Case.build(STRAND, STEPS, title="7-wire strand bent under tension", contact={"friction": 0.3},
                                output={"vtu": False}, name="friction_sweep")
    table = strandfem.sweep(case, [0.1, 0.3, 0.5], out, key="contact.friction", processes=2)
    refs = case.references()
    print(table[["contact.friction", "status", "peak_deflection_mm", "loop_area_Nmm", "secant_ei_Nm2"]].to_string(index=False))
    print(f"EImax {refs['ei_max_Nm2']:.1f} N m2, EImin {refs['ei_min_Nm2']:.2f} N m2")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for mu, folder in zip(table["contact.friction"], table["folder"]):
        h = strandfem.read_results(folder).history
        bend = h[h["cycle"] > 0]
        ax.plot(bend["midspan_deflection_mm"], bend["transverse_load_N"], label=f"μ = {mu}")
    ax.set_xlabel("midspan deflection (mm)")
    ax.set_ylabel("transverse load V (N)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "loops.png"), dpi=120)
    print("loops drawn in", os.path.join(out, "loops.png"))
