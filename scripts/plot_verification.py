#!/usr/bin/python3
"""Runs the verification cases through the program and plots them against their closed forms.

Usage: scripts/plot_verification.py [build/apps/strandfem [OUT_DIR]] -> docs/verification_rollup.png,
docs/verification_seven_wire.png (or into OUT_DIR) and the numbers printed for docs/verification.md.
"""
import csv, math, os, subprocess, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build/apps/strandfem")
figures = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "docs")


def run(case, out):
    subprocess.run([exe, "run", os.path.join(root, case), "-q", "-o", out], check=True)
    with open(os.path.join(out, "history.csv")) as f:
        return list(csv.DictReader(f))


rows = run("cases/verification/cantilever_roll_up.yaml", "/tmp/strandfem_plot_rollup")
L = 100.0
fig, ax = plt.subplots(figsize=(5, 5))
lam = [i / 200 for i in range(1, 201)]
ax.plot([math.sin(2 * math.pi * l) / (2 * math.pi * l / L) for l in lam],
        [(1 - math.cos(2 * math.pi * l)) / (2 * math.pi * l / L) for l in lam], "k-", label="exact tip path")
ax.plot([L + float(r["monitor_ux_mm"]) for r in rows], [float(r["monitor_uy_mm"]) for r in rows], "o", label="StrandFEM, 10 elements")
worst = max(math.hypot(L + float(r["monitor_ux_mm"]) - math.sin(2 * math.pi * float(r["load_factor"])) / (2 * math.pi * float(r["load_factor"]) / L),
                       float(r["monitor_uy_mm"]) - (1 - math.cos(2 * math.pi * float(r["load_factor"]))) / (2 * math.pi * float(r["load_factor"]) / L)) for r in rows)
print(f"roll-up: largest tip position error over 20 increments = {worst:.2e} mm")
ax.set_xlabel("x (mm)"); ax.set_ylabel("y (mm)"); ax.set_aspect("equal"); ax.legend(); ax.set_title("Cantilever rolled up by an end moment")
fig.tight_layout(); fig.savefig(os.path.join(figures, "verification_rollup.png"), dpi=110)

rows = run("cases/examples/seven_wire_axial.yaml", "/tmp/strandfem_plot_seven")
fig, ax = plt.subplots(figsize=(6, 4))
eps = [0] + [float(r["axial_strain"]) for r in rows]
force = [0] + [float(r["axial_force_N"]) / 1000 for r in rows]
ax.plot(eps, force, "o-", label="StrandFEM, wires tied at the ends only (no contact)")
ax.plot([0, 0.01], [0, 0.01 * 188000 * math.pi * 3.94 ** 2 / 4 / 1000], "k--", label="core alone, E A eps")
ax.plot([0, 0.01], [0, 0.01 * 13854455 / 1000], "k:", label="linear strand theory, fixed ends (C11 eps)")
ax.set_xlabel("axial strain"); ax.set_ylabel("axial force (kN)"); ax.legend(fontsize=8); ax.set_title("7-wire strand (Table 1), no contact")
fig.tight_layout(); fig.savefig(os.path.join(figures, "verification_seven_wire.png"), dpi=110)
print("seven-wire: force at 1 % strain =", rows[-1]["axial_force_N"], "N")
