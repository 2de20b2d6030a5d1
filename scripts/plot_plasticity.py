#!/usr/bin/python3
"""Plots the elastoplastic strands from finished runs (paper section 3.1):

- Fig. 4: axial load against strain of the 7-wire strand, fixed and free ends, beside the linear theory;
- Fig. 5a: von Mises stress along the wires of the 120-wire strand at strain 0.0056 (end of step 1), a
  partial view (z <= 60 mm) drawn from wires.csv at the wires' reference positions;
- Fig. 5b: axial load against strain of the 120-wire strand beside Judge et al.'s 3D solid model and the
  experiment (data/reference/judge2012_120wire_axial.csv).

Usage:
  strandfem run cases/paper/seven_wire_plastic_fixed.yaml -o RUNS/seven_fixed   (same for _free, wire_120_plastic)
  scripts/plot_plasticity.py RUNS [OUT_DIR] -> docs/validation_plasticity.png, docs/validation_wire_120_von_mises.png
  (or into OUT_DIR), and the comparison numbers printed for docs/validation.md. Missing runs are skipped.
"""
import csv, json, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib import cm, colors

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
runs = sys.argv[1] if len(sys.argv) > 1 else "/tmp/strandfem_plasticity"
figures = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "docs")


def history(name):
    path = os.path.join(runs, name, "history.csv")
    return list(csv.DictReader(open(path))) if os.path.exists(path) else None


def curve(rows):
    return [0.0] + [float(r["axial_strain"]) for r in rows], [0.0] + [float(r["axial_force_N"]) / 1e3 for r in rows]


def interpolate(xs, ys, x):
    for i in range(1, len(xs)):
        if xs[i - 1] <= x <= xs[i]:
            t = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return ys[i - 1] + t * (ys[i] - ys[i - 1])
    return None


fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
for name, label, style in (("seven_fixed", "fixed ends", "b-"), ("seven_free", "free ends", "r-")):
    rows = history(name)
    if not rows:
        continue
    x, y = curve(rows)
    a1.plot(x, y, style, label="StrandFEM, " + label)
    summary = json.load(open(os.path.join(runs, name, "summary.json")))
    k = summary["axial_stiffness_N"]["fixed_ends" if name == "seven_fixed" else "free_ends"]
    a1.plot([0, 0.0082], [0, k * 0.0082 / 1e3], style[0] + ":", label="linear theory, " + label)
    print(f"7-wire {label}: {summary['wall_time_s']:.1f} s, load at 0.015 = {y[-1]:.1f} kN, "
          f"slope at 0.004 / theory = {interpolate(x, y, 0.004) * 1e3 / 0.004 / k:.4f}")
a1.axvline(1540 / 188000, color="grey", lw=0.6)
a1.set_xlabel("strand axial strain")
a1.set_ylabel("axial load (kN)")
a1.set_title("7-wire strand (Table 1), Fig. 4")
a1.legend(fontsize=8)

judge_path = os.path.join(root, "data", "reference", "judge2012_120wire_axial.csv")
series = {}
if os.path.exists(judge_path):
    for line in open(judge_path):
        if line.startswith("#") or line.startswith("series"):
            continue
        s, e, f = line.strip().split(",")
        series.setdefault(s, ([], []))
        series[s][0].append(float(e))
        series[s][1].append(float(f) / 1e3)
for s, (label, style) in {"exp": ("experiment (Judge et al.)", "ko"), "solid3d": ("3D solid model (Judge et al.)", "gs--")}.items():
    if s in series:
        a2.plot(series[s][0], series[s][1], style, ms=4, label=label)
rows = history("wire_120")
if rows:
    x, y = curve(rows)
    a2.plot(x, y, "b-", label="StrandFEM")
    summary = json.load(open(os.path.join(runs, "wire_120", "summary.json")))
    k = summary["axial_stiffness_N"]["fixed_ends"]
    a2.plot([0, 0.01], [0, k * 0.01 / 1e3], "b:", label="linear theory (fixed ends)")
    print(f"120-wire: {summary['wall_time_s']:.1f} s, {len(rows)} increments, status {summary['status']}, "
          f"elements {summary['elements']}, nodes {summary['nodes']}, contacts {summary.get('contacts')}")
    if "solid3d" in series:
        for e, f in zip(*series["solid3d"]):
            if e >= 0.0134:
                ours = interpolate(x, y, e)
                if ours is None:
                    print(f"  strain {e:.4f}: solid {f:.0f} kN, beyond the run")
                    continue
                print(f"  strain {e:.4f}: solid {f:.0f} kN, StrandFEM {ours:.0f} kN, difference {100 * (ours / f - 1):+.1f} %")
a2.set_xlabel("strand axial strain")
a2.set_ylabel("axial load (kN)")
a2.set_title("120-wire strand (Table 3), Fig. 5b")
a2.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(figures, "validation_plasticity.png"), dpi=120)

# Fig. 5a: von Mises along the wires at the end of step 1 (strain 0.0056), z <= 60 mm.
wires_path = os.path.join(runs, "wire_120", "wires.csv")
if os.path.exists(wires_path):
    import math
    nodes = [w for w in csv.DictReader(open(wires_path)) if w["step"] == "1" and float(w["z_mm"]) <= 60]
    last = max(int(w["increment"]) for w in nodes)
    nodes = [w for w in nodes if int(w["increment"]) == last]
    norm = colors.Normalize(vmin=200, vmax=1300)  # the paper's colour scale (MPa)
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="3d")
    by_wire = {}
    for w in nodes:
        by_wire.setdefault(int(w["wire"]), []).append(w)
    for wire, points in by_wire.items():
        points.sort(key=lambda w: float(w["z_mm"]))
        xs = [float(w["radius_mm"]) * math.cos(math.radians(float(w["angle_deg"]))) for w in points]
        ys = [float(w["radius_mm"]) * math.sin(math.radians(float(w["angle_deg"]))) for w in points]
        zs = [float(w["z_mm"]) for w in points]
        vm = [float(w["max_von_mises_MPa"]) for w in points]
        for i in range(len(points) - 1):
            ax.plot(xs[i:i + 2], ys[i:i + 2], zs[i:i + 2], color=cm.jet(norm(0.5 * (vm[i] + vm[i + 1]))), lw=2.5)
    fig.colorbar(cm.ScalarMappable(norm=norm, cmap="jet"), ax=ax, shrink=0.6, label="von Mises, largest over the section (MPa)")
    ax.set_title("120-wire strand at strain 0.0056 (Fig. 5a), z <= 60 mm")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_zlabel("z (mm)")
    fig.savefig(os.path.join(figures, "validation_wire_120_von_mises.png"), dpi=120)
    layers = {}
    for w in nodes:
        if 20 <= float(w["z_mm"]) <= 60:
            layers.setdefault(int(w["layer"]), []).append(float(w["max_von_mises_MPa"]))
    for layer, v in sorted(layers.items()):
        print(f"  strain 0.0056, layer {layer}: von Mises {min(v):.0f} to {max(v):.0f} MPa (20 <= z <= 60 mm)")
