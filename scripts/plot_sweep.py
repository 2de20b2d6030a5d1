#!/usr/bin/python3
"""Plots the cases of a `strandfem sweep` folder on one figure, sweep.png:

- bending cases (a transverse load in history.csv): midspan load V against midspan deflection, every cycle, with
  eq. 3.1's EImax and EImin lines up to the peak load (from the first variant's summary.json that has a loop);
  beside it, where the variants wrote deflection_curves.csv, the curve at the first peak as the paper draws it
  (Figs. 8, 9a, 15a): the rise below the load point over 150 mm from it (the mean of both sides), with eq. 3.2's;
- where a bending variant ran two cycles or more, a panel as the paper draws its Cardinal loops (Fig. 9b, "the first
  transversal load application" removed): cycle 1's return half and cycle 2's loading half, shifted so that V = 0
  between them lies at zero deflection, labelled with that loop's area (loops.csv, return_loop_area_Nmm), with
  eq. 3.1's lines;
- axial cases: axial force against axial strain.

One curve per row of sweep.csv (its variant name in the legend); a variant without results is left out.

Usage: scripts/plot_sweep.py SWEEP_FOLDER
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def draw_eq31_bounds(ax, folder, variants):
    """Eq. 3.1's straight lines for EImax and EImin up to the first variant's peak load (summary.json), when known,
    within the curves' own range (their values at the peak in the legend)."""
    x_range = ax.get_xlim()
    for v in variants:
        path = os.path.join(folder, v["results"], "summary.json")
        if not os.path.exists(path):
            continue
        loops = json.load(open(path)).get("bending", {}).get("loops", [])
        if not loops:
            continue
        loop = loops[0]
        for key, name, style in (("eq31_ei_max_mm", "EImax", "--"), ("eq31_ei_min_mm", "EImin", ":")):
            ax.plot([0, loop[key]], [0, loop["peak_load_N"]], style, color="gray", linewidth=1,
                    label=f"{name} (eq. 3.1): {loop[key]:.3g} mm at the peak")
        break
    ax.set_xlim(*x_range)


def draw_deflection_curves(ax, folder, variants, span=150.0):
    """The curve at the first peak from the load point over `span` mm (the mean of both sides), each variant, with
    eq. 3.2's two curves of the first; False when no variant wrote deflection_curves.csv."""
    drawn = False
    for v in variants:
        path = os.path.join(folder, v["results"], "deflection_curves.csv")
        if not os.path.exists(path):
            continue
        rows = [r for r in csv.DictReader(open(path)) if r["cycle"] == "1" and abs(float(r["z_from_load_mm"])) <= span + 1e-9]
        if not rows:
            continue
        by_distance = {}
        for r in rows:
            by_distance.setdefault(round(abs(float(r["z_from_load_mm"])), 6), []).append(r)
        distances = sorted(by_distance)
        mean = lambda key: [sum(float(r[key]) for r in by_distance[d]) / len(by_distance[d]) for d in distances]
        if not drawn:
            for key, name, style in (("eq32_ei_max_rise_mm", "EImax (eq. 3.2)", "--"), ("eq32_ei_min_rise_mm", "EImin (eq. 3.2)", ":")):
                ax.plot(distances, mean(key), style, color="gray", linewidth=1, label=name)
        ax.plot(distances, mean("rise_from_load_mm"), marker=".", markersize=3, linewidth=1, label=v["variant"])
        drawn = True
    if drawn:
        ax.set_xlim(0, span)
        ax.set_xlabel("distance from the load point (mm)")
        ax.set_ylabel("rise below the load point at the first peak (mm)")
        ax.set_title("the curve as the paper draws it (Figs. 8, 9a, 15a)", fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    return drawn


def return_loop_points(rows):
    """Cycle 1's return half (from its peak) and cycle 2's loading half, x from the V = 0 point between them; None
    without a second cycle."""
    cycle = [int(r.get("cycle", 0)) for r in rows]
    if 2 not in cycle:
        return None
    returning = [r.get("returning") == "1" for r in rows]
    peak = max(i for i in range(len(rows)) if cycle[i] == 1 and not returning[i])
    valley = max(i for i in range(len(rows)) if cycle[i] == 1)
    second_peak = max(i for i in range(len(rows)) if cycle[i] == 2 and not returning[i])
    part = rows[peak:second_peak + 1]
    x0 = float(rows[valley]["midspan_deflection_mm"])
    return ([float(r["midspan_deflection_mm"]) - x0 for r in part], [float(r["transverse_load_N"]) for r in part])


def draw_return_loops(ax, folder, variants, curves):
    """The paper's presentation of each variant with a second cycle; False when none has one."""
    drawn = False
    for name, rows in curves:
        points = return_loop_points(rows)
        if points is None:
            continue
        label = name
        loops_path = os.path.join(folder, next(v["results"] for v in variants if v["variant"] == name), "loops.csv")
        loops = list(csv.DictReader(open(loops_path))) if os.path.exists(loops_path) else []
        if len(loops) > 1 and loops[1].get("return_loop_area_Nmm"):
            label += f": {float(loops[1]['return_loop_area_Nmm']) / 1000:.3g} N m"
        ax.plot(points[0], points[1], marker=".", markersize=3, linewidth=1, label=label)
        drawn = True
    if drawn:
        draw_eq31_bounds(ax, folder, variants)
        ax.set_xlabel("midspan deflection from V = 0 after cycle 1 (mm)")
        ax.set_ylabel("transverse load V (N)")
        ax.set_title("cycle 1's return and cycle 2's loading (paper, Fig. 9b)", fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    return drawn


def main(folder):
    variants = list(csv.DictReader(open(os.path.join(folder, "sweep.csv"))))
    curves = []
    for v in variants:
        path = os.path.join(folder, v["results"], "history.csv")
        if not os.path.exists(path):
            continue
        rows = list(csv.DictReader(open(path)))
        if rows:
            curves.append((v["variant"], rows))
    if not curves:
        print("no results to plot in", folder)
        return 1
    bending = any(abs(float(r["transverse_load_N"])) > 0 for _, rows in curves for r in rows)
    has_curves = bending and any(os.path.exists(os.path.join(folder, v["results"], "deflection_curves.csv")) for v in variants)
    has_return = bending and any(return_loop_points(rows) is not None for _, rows in curves)
    panels = 1 + has_curves + has_return
    fig, axes = plt.subplots(1, panels, figsize=(5.5 * panels if panels > 1 else 6.4, 4.6), squeeze=False)
    axes = list(axes[0])
    if has_curves:
        draw_deflection_curves(axes.pop(0), folder, variants)
    ax = axes.pop(0)
    if has_return:
        draw_return_loops(axes.pop(0), folder, variants, curves)
    for name, rows in curves:
        if bending:
            # From the end of the tension ramp on: the state before the first transverse increment starts the loop.
            start = next(i for i, r in enumerate(rows) if abs(float(r["transverse_load_N"])) > 0)
            part = rows[max(0, start - 1):]
            x = [float(r["midspan_deflection_mm"]) - float(part[0]["midspan_deflection_mm"]) for r in part]
            y = [float(r["transverse_load_N"]) for r in part]
        else:
            x = [0.0] + [float(r["axial_strain"]) for r in rows]
            y = [0.0] + [float(r["axial_force_N"]) / 1000 for r in rows]
        ax.plot(x, y, marker=".", markersize=3, linewidth=1, label=name)
    if bending:
        draw_eq31_bounds(ax, folder, variants)
        ax.set_xlabel("midspan deflection from the start of bending (mm)")
        ax.set_ylabel("transverse load V (N)")
    else:
        ax.set_xlabel("axial strain")
        ax.set_ylabel("axial force (kN)")
    fig.suptitle(os.path.basename(os.path.abspath(folder)), fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.join(folder, "sweep.png")
    fig.savefig(out, dpi=130)
    print(out)
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
