#!/usr/bin/python3
"""Plots the curve from the load point at Vmax (paper Figs. 8, 9a, 15a) for V on the core node, through a rigid
section and through saddles: docs/validation_bending_from_load_point.png.

Each panel is one strand and load case (S32 cases 1 to 4, Cardinal with mu_a 0.5): the rise below the load point
over 150 mm from it, the mean of both sides, read from the core's nodes in each run's displacements.csv (the state
at Vmax: the cases of cases/studies/load_point/ end at the peak), beside eq. 3.2 for EImax and EImin and the top
of the paper's chart.

Usage:
  strandfem run cases/studies/load_point/NAME.yaml -o RUNS/NAME   (for each case file there)
  scripts/plot_load_point.py RUNS [-o docs/validation_bending_from_load_point.png]
Missing runs are left out of their panel.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LENGTH = 1000.0  # mm between the clamps, every case here
LOAD_Z = 500.0  # mm, V at midspan
SPAN = 150.0  # mm from the load point, as the paper's charts

# (title, V N, T N, EImax N mm², EImin N mm² (the paper's Tables 4 and 5), top of the paper's chart mm,
#  [(results folder = case file name, label)])
PANELS = (
    ("S32 case 1: T 40 kN, V 5 kN", 5000.0, 40000.0, 6357.8e6, 82.7e6, 4.0,
     (("s32_case1_core", "V on the core node"), ("s32_case1_section", "rigid section"),
      ("s32_case1_saddle45", "saddle 45 mm"), ("s32_case1_saddle90", "saddle 90 mm"),
      ("s32_case1_saddle150", "saddle 150 mm"))),
    ("S32 case 2: T 80 kN, V 10 kN", 10000.0, 80000.0, 6357.8e6, 82.7e6, 4.0,
     (("s32_case2_core", "V on the core node"), ("s32_case2_saddle150", "saddle 150 mm"))),
    ("S32 case 3: T 140 kN, V 20 kN", 20000.0, 140000.0, 6357.8e6, 82.7e6, 8.0,
     (("s32_case3_core", "V on the core node"), ("s32_case3_saddle90", "saddle 90 mm"))),
    ("S32 case 4: T 280 kN, V 40 kN", 40000.0, 280000.0, 6357.8e6, 82.7e6, 4.0,
     (("s32_case4_core", "V on the core node"), ("s32_case4_saddle90", "saddle 90 mm"),
      ("s32_case4_saddle150", "saddle 150 mm"))),
    ("Cardinal: T 40 kN, V 4.3 kN, μa 0.5", 4300.0, 40000.0, 1800.4e6, 28.3e6, 2.0,
     (("cardinal_core", "V on the core node"), ("cardinal_saddle90", "saddle 90 mm"),
      ("cardinal_saddle150", "saddle 150 mm"))),
)


def eq32_deflection(V, T, EI, L, x):
    """Eq. 3.2: deflection of a beam of bending stiffness EI under tension T, clamped at both ends, with V at
    midspan, at x from the nearer clamp (0 <= x <= L/2):
    y = V k / (2T) (x/k - sinh(x/k) + tanh(L / 4k) (cosh(x/k) - 1)), with k = sqrt(EI / T)."""
    k = math.sqrt(EI / T)
    return V * k / (2 * T) * (x / k - math.sinh(x / k) + math.tanh(L / (4 * k)) * (math.cosh(x / k) - 1))


def eq32_rise(V, T, EI, distances):
    """Eq. 3.2's rise below the load point: its deflection there less the deflection at each distance from it."""
    at_load = eq32_deflection(V, T, EI, LENGTH, LOAD_Z)
    return [at_load - eq32_deflection(V, T, EI, LENGTH, LOAD_Z - d) for d in distances]


def interpolate(xs, ys, x):
    """Linear interpolation in the increasing xs."""
    for i in range(1, len(xs)):
        if xs[i - 1] <= x <= xs[i]:
            t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 0.0
            return ys[i - 1] + t * (ys[i] - ys[i - 1])
    raise ValueError(f"z = {x} mm is outside the core's nodes")


def model_rise(folder, distances):
    """The run's rise below the load point at each distance, the mean of both sides, from the core's uy."""
    with open(os.path.join(folder, "displacements.csv")) as f:
        core = sorted((float(r["z0"]), float(r["uy"])) for r in csv.DictReader(f) if r["layer"] == "0")
    z = [p[0] for p in core]
    uy = [p[1] for p in core]
    at_load = interpolate(z, uy, LOAD_Z)
    return [at_load - 0.5 * (interpolate(z, uy, LOAD_Z - d) + interpolate(z, uy, LOAD_Z + d)) for d in distances]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", help="folder holding one results folder per case of cases/studies/load_point/")
    parser.add_argument("-o", "--output", default=os.path.join(ROOT, "docs", "validation_bending_from_load_point.png"))
    args = parser.parse_args()
    fig, grid = plt.subplots(2, 3, figsize=(15, 9))
    axes = grid.flat
    grid.flat[-1].axis("off")
    smooth = [float(d) for d in range(int(SPAN) + 1)]
    sampled = [5.0 * i for i in range(int(SPAN / 5) + 1)]
    for ax, (title, V, T, ei_max, ei_min, chart, runs) in zip(axes, PANELS):
        ax.plot(smooth, eq32_rise(V, T, ei_max, smooth), "k--", lw=1, label="EImax (eq. 3.2)")
        ax.plot(smooth, eq32_rise(V, T, ei_min, smooth), "k:", lw=1, label="EImin (eq. 3.2)")
        for name, label in runs:
            folder = os.path.join(args.runs, name)
            if not os.path.exists(os.path.join(folder, "displacements.csv")):
                print(f"{folder}: no displacements.csv, left out")
                continue
            ax.plot(sampled, model_rise(folder, sampled), "-o", ms=2, lw=1, label=label)
        ax.axhline(chart, color="tab:red", lw=0.8, alpha=0.6, label=f"top of the paper's chart ({chart:g} mm)")
        ax.set_xlim(0, SPAN)
        ax.set_ylim(0, max(chart * 2.2, 5))
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("distance from the load point (mm)")
        ax.set_ylabel("rise below the load point at Vmax (mm)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(args.output)


if __name__ == "__main__":
    main()
