#!/usr/bin/python3
"""Runs the 7-wire strand of the paper's Table 1 (fixed and free ends, mu = 0.115) and plots axial load
against strain beside Costello's linear theory, and the core-wire contact force per length beside Table 2.

Usage: scripts/plot_validation.py [build/apps/strandfem [OUT_DIR]] -> docs/validation_seven_wire.png (or into
OUT_DIR) and the numbers printed for docs/validation.md.
"""
import csv, json, os, subprocess, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build/apps/strandfem")
figures = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "docs")
out = "/tmp/strandfem_validation_fixed"
subprocess.run([exe, "run", os.path.join(root, "cases/paper/seven_wire_fixed.yaml"), "-q", "-o", out], check=True)
rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
summary = json.load(open(os.path.join(out, "summary.json")))
k_fixed = summary["axial_stiffness_N"]["fixed_ends"]
k_free = summary["axial_stiffness_N"]["free_ends"]
free_out = "/tmp/strandfem_validation_free"
subprocess.run([exe, "run", os.path.join(root, "cases/paper/seven_wire_free.yaml"), "-q", "-o", free_out], check=True)
free_rows = list(csv.DictReader(open(os.path.join(free_out, "history.csv"))))
free_summary = json.load(open(os.path.join(free_out, "summary.json")))
strain = [float(r["axial_strain"]) for r in rows]
force = [float(r["axial_force_N"]) for r in rows]
table = list(csv.DictReader(open(os.path.join(root, "tests/verification/data/table2_core_wire_contact_force.csv"))))
contacts = list(csv.DictReader(open(os.path.join(out, "contacts.csv"))))
p_model = {}
for t in table:
    e = float(t["axial_strain"])
    inc = [r["increment"] for r in rows if abs(float(r["axial_strain"]) - e) < 1e-9]
    if not inc:
        continue
    values = [float(c["normal_force"]) for c in contacts
              if c["increment"] == inc[0] and c["wire_b"] == "0" and 50 <= float(c["z_mm"]) <= 150]
    p_model[e] = sum(values) / len(values)

fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
a1.plot([0, 0.008], [0, k_fixed * 0.008 / 1000], "k-", label="Costello, fixed ends")
a1.plot([0, 0.008], [0, k_free * 0.008 / 1000], "k--", label="Costello, free ends")
a1.plot(strain, [f / 1000 for f in force], "o", label="StrandFEM, fixed ends")
a1.plot([float(r["axial_strain"]) for r in free_rows], [float(r["axial_force_N"]) / 1000 for r in free_rows], "s",
        markersize=3, label="StrandFEM, free ends")
a1.set_xlabel("axial strain")
a1.set_ylabel("axial load (kN)")
a1.set_title("7-wire strand (Table 1), mu = 0.115")
a1.legend()
es = sorted(p_model)
a2.plot(es, [p_model[e] for e in es], "o-", label="StrandFEM (50 <= z <= 150 mm)")
a2.plot([float(t["axial_strain"]) for t in table], [float(t["p_ref_jiang_henshall_N_per_mm"]) for t in table], "s--", label="Jiang & Henshall (ref. [26])")
a2.plot([float(t["axial_strain"]) for t in table], [float(t["p_paper_beam_model_N_per_mm"]) for t in table], "^:", label="paper's beam model")
a2.set_xlabel("axial strain")
a2.set_ylabel("core-wire contact force p (N/mm)")
a2.set_title("Table 2")
a2.legend()
fig.tight_layout()
fig.savefig(os.path.join(figures, "validation_seven_wire.png"), dpi=110)
slope = force[-1] / strain[-1]
print(f"slope {slope:.6g} N, Costello fixed {k_fixed:.6g} N, ratio {slope / k_fixed:.5f}")
for t in table:
    e = float(t["axial_strain"])
    if e in p_model:
        ref, paper = float(t["p_ref_jiang_henshall_N_per_mm"]), float(t["p_paper_beam_model_N_per_mm"])
        print(f"eps {e}: p = {p_model[e]:.1f} N/mm, ref {ref} ({100 * (p_model[e] / ref - 1):+.1f} %), paper {paper} ({100 * (p_model[e] / paper - 1):+.1f} %)")
print("contacts:", summary["contacts"], "wall", summary["wall_time_s"])
fe, ff, fr = (float(free_rows[-1][k]) for k in ("axial_strain", "axial_force_N", "end_rotation_rad"))
twist = free_summary["axial_stiffness_N"]["free_end_twist_rad_per_mm_per_strain"] * fe * 200.0
print(f"free: slope {ff / fe:.6g} N, Costello free {k_free:.6g} N, ratio {ff / fe / k_free:.5f}; "
      f"end rotation {fr:.5f} rad, Costello {twist:.5f} rad, ratio {fr / twist:.5f}; "
      f"{len(free_rows)} increments, wall {free_summary['wall_time_s']:.1f} s")
