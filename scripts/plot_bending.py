#!/usr/bin/python3
"""Plots a bending-under-tension results folder (a case with a cyclic transverse-load step, paper sections 3.2-5):

- bending_hysteresis.png: midspan load V against deflection for every cycle (history.csv), with the straight
  lines of eq. 3.1 for EImax and EImin from the start of the first cycle to the peak load (loops.csv);
- bending_deflection.png: the core's deflection along the strand at each cycle's peak load beside eq. 3.2 for
  EImax and EImin (deflection_curves.csv).

Usage: scripts/plot_bending.py RESULTS_FOLDER [...]   (PNGs are written into each folder)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(folder, name):
    path = os.path.join(folder, name)
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def save(fig, ax, xlabel, ylabel, path):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def plot_folder(folder):
    history = rows(folder, "history.csv")
    loops = rows(folder, "loops.csv")
    curves = rows(folder, "deflection_curves.csv")
    cyclic = [r for r in history if int(r.get("cycle", 0)) > 0]
    if not cyclic:
        print(f"{folder}: no cyclic step, nothing to plot")
        return []
    written = []
    fig, ax = plt.subplots(figsize=(6, 4.5))
    first = history.index(cyclic[0])
    start = history[first - 1] if first > 0 else cyclic[0]
    y0 = float(start["midspan_deflection_mm"])
    cycles = sorted({int(r["cycle"]) for r in cyclic})
    for c in cycles:
        pts = [start] if c == cycles[0] else []
        pts += [r for r in cyclic if int(r["cycle"]) == c]
        ax.plot([float(r["midspan_deflection_mm"]) - y0 for r in pts], [float(r["transverse_load_N"]) for r in pts],
                "-o", ms=2.5, lw=1, label=f"cycle {c}")
    if loops:
        peak = float(loops[0]["peak_load_N"])
        for key, style, label in (("eq31_ei_max_mm", "k--", "EImax (eq. 3.1)"), ("eq31_ei_min_mm", "k:", "EImin (eq. 3.1)")):
            ax.plot([0, float(loops[0][key])], [0, peak], style, lw=1, label=label)
    written.append(save(fig, ax, "midspan deflection (mm), from the start of the first cycle", "transverse load V (N)",
                        os.path.join(folder, "bending_hysteresis.png")))
    if curves:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for c in sorted({int(r["cycle"]) for r in curves}):
            pts = [r for r in curves if int(r["cycle"]) == c]
            z = [float(r["z_mm"]) for r in pts]
            ax.plot(z, [float(r["deflection_mm"]) for r in pts], "-", lw=1, label=f"model, cycle {c}")
            if c == 1:
                ax.plot(z, [float(r["eq32_ei_max_mm"]) for r in pts], "k--", lw=1, label="EImax (eq. 3.2)")
                ax.plot(z, [float(r["eq32_ei_min_mm"]) for r in pts], "k:", lw=1, label="EImin (eq. 3.2)")
        written.append(save(fig, ax, "axial position z (mm)", "core deflection at peak V (mm)",
                            os.path.join(folder, "bending_deflection.png")))
    return written


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    for folder in sys.argv[1:]:
        for path in plot_folder(folder):
            print(path)
