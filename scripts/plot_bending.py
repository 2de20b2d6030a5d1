#!/usr/bin/python3
"""Plots a bending-under-tension results folder (a case with a cyclic transverse-load step, paper sections 3.2-5):

- bending_hysteresis.png: midspan load V against deflection for every cycle (history.csv), with the straight
  lines of eq. 3.1 for EImax and EImin from the start of the first cycle to the peak load (loops.csv); each
  later cycle's label gives its loop's change against the cycle before and whether it is steady, and the area of
  the loop from the previous peak (the previous return and this loading: the paper's Fig. 9b presentation);
- bending_deflection.png: the core's deflection along the strand at each cycle's peak load beside eq. 3.2 for
  EImax and EImin, and EImin with the wires' shear (deflection_curves.csv), titled with summary.json's check of
  the first peak's curve against those bounds; beside it, the curve as the paper draws it (Figs. 8, 9a, 15a):
  the rise below the load point over 150 mm either side, with eq. 3.2's;
- bending_wire_forces.png: wire axial force F at the first cycle's peak load and its change dF since V = 0,
  along the half strand, for the wires near the plane of the load and near the plane across it (paper
  Figs. 12-13; wire_profiles.csv);
- bending_contact_forces.png: P, dP, Q, dQ, delta (sliding plus elastic slip) and its change at the crossings
  between layers, same regions (paper Fig. 14; contact_profiles.csv);
- bending_status_maps.png: sticking / sliding / slipping of the crossings at the first cycle's peak load over
  axial and angular position, one panel per layer interface, from the clamp edge (paper Fig. 11).

Usage: scripts/plot_bending.py RESULTS_FOLDER [...]   (PNGs are written into each folder)
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(folder, name):
    path = os.path.join(folder, name)
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def save(fig, ax, xlabel, ylabel, path, legend_below=False):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    if legend_below:  # long labels (one per cycle) would hide the loops' lower ends
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.0, -0.12))
    else:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return path


def energy(value_nmm):
    """An energy from N mm, written in N m from 1 N m on (3 significant digits, never in powers of ten)."""
    value = float(value_nmm)
    if abs(value) >= 1e3:
        return f"{value / 1000:#.3g} N m".replace(". N", " N")
    return f"{value:#.3g} N mm".replace(". N", " N")


def plot_folder(folder):
    history = rows(folder, "history.csv")
    loops = rows(folder, "loops.csv")
    curves = rows(folder, "deflection_curves.csv")
    cyclic = [r for r in history if int(r.get("cycle", 0)) > 0]
    if not cyclic:
        print(f"{folder}: no cyclic step, nothing to plot")
        return []
    written = []
    fig, ax = plt.subplots(figsize=(6, 5.5))
    first = history.index(cyclic[0])
    start = history[first - 1] if first > 0 else cyclic[0]
    y0 = float(start["midspan_deflection_mm"])
    cycles = sorted({int(r["cycle"]) for r in cyclic})
    loop_of = {int(r["cycle"]): r for r in loops}
    for c in cycles:
        pts = [start] if c == cycles[0] else []
        pts += [r for r in cyclic if int(r["cycle"]) == c]
        label = f"cycle {c}"
        if c in loop_of and "friction_dissipation_Nmm" in loop_of[c]:
            # The loop's area is friction's work plus the set the cycle locks in (docs/theory.md, "Loops").
            label += (f": loop {energy(loop_of[c]['area_Nmm'])}, friction "
                      f"{energy(loop_of[c]['friction_dissipation_Nmm'])}")
        if c in loop_of and loop_of[c].get("area_change"):
            # Against the cycle before (loops.csv); steady by the case's output.steady_tolerance.
            label += f", {100 * float(loop_of[c]['area_change']):+.1f} % on cycle {c - 1}"
            if loop_of[c].get("steady") == "1":
                label += " (steady)"
        if c in loop_of and loop_of[c].get("return_loop_area_Nmm"):
            # Cycle c - 1's return and this loading, peak to peak: the loop as the paper draws it (Fig. 9b).
            label += f"; from peak {c - 1}: {energy(loop_of[c]['return_loop_area_Nmm'])}"
        ax.plot([float(r["midspan_deflection_mm"]) - y0 for r in pts], [float(r["transverse_load_N"]) for r in pts],
                "-o", ms=2.5, lw=1, label=label)
    # The loop fills the plot: the references are drawn up to its edge and their values at the peak go in the legend.
    x_low, x_high = ax.get_xlim()
    if loops:
        peak = float(loops[0]["peak_load_N"])
        for key, style, name in (("eq31_ei_max_mm", "k--", "EImax"), ("eq31_ei_min_mm", "k:", "EImin")):
            at_peak = float(loops[0][key])
            ax.plot([0, at_peak], [0, peak], style, lw=1, label=f"{name} (eq. 3.1): {at_peak:.3g} mm at the peak")
    ax.set_xlim(x_low, x_high)
    written.append(save(fig, ax, "midspan deflection (mm), from the start of the first cycle", "transverse load V (N)",
                        os.path.join(folder, "bending_hysteresis.png"), legend_below=True))
    if curves:
        fig, (ax, near) = plt.subplots(1, 2, figsize=(11, 4.5))
        for c in sorted({int(r["cycle"]) for r in curves}):
            pts = [r for r in curves if int(r["cycle"]) == c]
            z = [float(r["z_mm"]) for r in pts]
            ax.plot(z, [float(r["deflection_mm"]) for r in pts], "-", lw=1, label=f"model, cycle {c}")
            if c == 1:
                ax.plot(z, [float(r["eq32_ei_max_mm"]) for r in pts], "k--", lw=1, label="EImax (eq. 3.2)")
                ax.plot(z, [float(r["eq32_ei_min_mm"]) for r in pts], "k:", lw=1, label="EImin (eq. 3.2)")
                if "eq32_ei_min_shear_mm" in pts[0]:
                    ax.plot(z, [float(r["eq32_ei_min_shear_mm"]) for r in pts], "k-.", lw=0.8,
                            label="EImin with the wires' shear")
            if "rise_from_load_mm" in pts[0]:
                draw_rise_from_load(near, pts, c)
        check = curve_check_title(folder)
        if check:
            ax.set_title(check, fontsize=8)
        ax.set_xlabel("axial position z (mm)")
        ax.set_ylabel("core deflection at peak V (mm)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        written.append(save(fig, near, "distance from the load point (mm), both sides",
                            "rise below the load point at peak V (mm)", os.path.join(folder, "bending_deflection.png")))
    written += plot_profiles(folder)
    return written


def draw_rise_from_load(ax, pts, cycle, span=150.0):
    """The curve as the paper's Figs. 8, 9a and 15a draw it: each side's rise below the load point over `span` mm,
    beside eq. 3.2's (the first cycle draws the references)."""
    near = [r for r in pts if abs(float(r["z_from_load_mm"])) <= span + 1e-9]
    for side, style in ((-1, "-"), (1, "--")):
        half = sorted((abs(float(r["z_from_load_mm"])), float(r["rise_from_load_mm"])) for r in near
                      if side * float(r["z_from_load_mm"]) >= 0)
        ax.plot([d for d, _ in half], [y for _, y in half], style, lw=1,
                label=f"model, cycle {cycle}, {'towards z = 0' if side < 0 else 'towards z = L'}")
    if cycle == 1:
        half = sorted((abs(float(r["z_from_load_mm"])), float(r["eq32_ei_max_rise_mm"]), float(r["eq32_ei_min_rise_mm"]))
                      for r in near if float(r["z_from_load_mm"]) >= 0)
        ax.plot([d for d, _, _ in half], [y for _, y, _ in half], "k--", lw=1, label="EImax (eq. 3.2)")
        ax.plot([d for d, _, _ in half], [y for _, _, y in half], "k:", lw=1, label="EImin (eq. 3.2)")
    ax.set_xlim(0, span)


def curve_check_title(folder):
    """summary.json's check of the first peak's curve against eq. 3.2's bounds, in one line (empty if absent)."""
    path = os.path.join(folder, "summary.json")
    if not os.path.exists(path):
        return ""
    checks = json.load(open(path)).get("bending", {}).get("deflection_curves", [])
    if not checks:
        return ""
    first = checks[0]["all_nodes"]
    text = f"cycle {checks[0]['cycle']}: {first['within']} of {first['nodes']} nodes between eq. 3.2's bounds"
    if first["largest_excess_mm"] > 0:
        text += (f"; largest excess {100 * first['largest_excess_relative']:.2g} % "
                 f"at {first['largest_excess_x_mm']:g} mm from a clamp")
    if first["largest_shortfall_mm"] > 0:
        text += f"; below EImax by up to {first['largest_shortfall_mm']:.3g} mm"
    return text


REGIONS = (("vertical", "near the load's plane"), ("horizontal", "near the plane across it"))
STATUS_COLOURS = {"sticking": "tab:blue", "sliding": "tab:orange", "slipping": "tab:red", "frictionless": "tab:gray"}


def save_figure(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def interface(row):
    """The layer pair of a contact row, inner layer first."""
    a, b = int(row["layer_a"]), int(row["layer_b"])
    return min(a, b), max(a, b)


def half_length(rows_):
    """The half of the strand from a clamp to midspan (the paper's figures; the results are symmetric)."""
    return [r for r in rows_ if float(r["z_from_midspan_mm"]) <= 1e-9]


def plot_profiles(folder):
    written = []
    wires = [r for r in rows(folder, "wire_profiles.csv") if r["cycle"] == "1"]
    contacts = [r for r in rows(folder, "contact_profiles.csv") if r["cycle"] == "1" and r["kind"] == "point"]
    if wires:
        fig, axes = plt.subplots(2, 2, figsize=(10, 6.5), sharex=True)
        layers = sorted({int(r["layer"]) for r in wires if int(r["layer"]) > 0})
        for col, (region, title) in enumerate(REGIONS):
            for layer in layers:
                pts = [r for r in half_length(wires) if r["plane"] == region and int(r["layer"]) == layer]
                z = [float(r["z_from_midspan_mm"]) for r in pts]
                for row, key in enumerate(("axial_force_N", "delta_axial_force_N")):
                    axes[row][col].plot(z, [float(r[key]) for r in pts], ".", ms=3, label=f"layer {layer}")
            axes[0][col].set_title(f"wires {title}", fontsize=9)
            axes[0][col].set_ylabel("F at peak V (N)")
            axes[1][col].set_ylabel("dF since V = 0 (N)")
            axes[1][col].set_xlabel("axial position from midspan (mm)")
            for row in range(2):
                axes[row][col].grid(alpha=0.3)
            axes[0][col].legend(fontsize=7)
        written.append(save_figure(fig, os.path.join(folder, "bending_wire_forces.png")))
    if contacts:
        interfaces = sorted({interface(r) for r in contacts})
        quantities = (("normal_force", "P at peak V (N)"), ("delta_normal_force", "dP (N)"),
                      ("tangential_force", "Q at peak V (N)"), ("delta_tangential_force", "dQ (N)"),
                      ("tangential_displacement_mm", "delta at peak V (mm)"),
                      ("delta_tangential_displacement_mm", "delta since V = 0 (mm)"))
        fig, axes = plt.subplots(len(quantities), 2, figsize=(10, 13), sharex=True)
        for col, (region, title) in enumerate(REGIONS):
            for a, b in interfaces:
                pts = [r for r in half_length(contacts)
                       if r["plane"] == region and r["map_status"] != "open" and interface(r) == (a, b)]
                z = [float(r["z_from_midspan_mm"]) for r in pts]
                for row, (key, _) in enumerate(quantities):
                    axes[row][col].plot(z, [float(r[key]) for r in pts], ".", ms=3, label=f"layers {a}-{b}")
            axes[0][col].set_title(f"crossings {title}", fontsize=9)
            for row, (_, label) in enumerate(quantities):
                axes[row][col].set_ylabel(label, fontsize=8)
                axes[row][col].grid(alpha=0.3)
            axes[-1][col].set_xlabel("axial position from midspan (mm)")
            axes[0][col].legend(fontsize=7)
        written.append(save_figure(fig, os.path.join(folder, "bending_contact_forces.png")))

        summary_path = os.path.join(folder, "summary.json")
        offset = 0.0
        if os.path.exists(summary_path):
            offset = json.load(open(summary_path)).get("bending", {}).get("clamp_edge_offset_mm", 0.0)
        closed = [r for r in half_length(contacts) if r["map_status"] != "open"]
        z_end = min(float(r["z_from_midspan_mm"]) - float(r["z_mm"]) for r in contacts)  # the restrained end
        z_clamp = z_end + offset
        fig, axes = plt.subplots(len(interfaces), 1, figsize=(8, 2.6 * len(interfaces)), squeeze=False, sharex=True)
        for ax, (a, b) in zip(axes[:, 0], interfaces):
            pts = [r for r in closed if interface(r) == (a, b) and float(r["z_from_midspan_mm"]) >= z_clamp]
            for status, colour in STATUS_COLOURS.items():
                sel = [r for r in pts if r["map_status"] == status]
                if sel:
                    ax.scatter([float(r["z_from_midspan_mm"]) for r in sel], [float(r["angle_deg"]) % 360 for r in sel], s=6,
                               c=colour, label=f"{status} ({len(sel)})")
            ax.axvspan(z_end, z_clamp, color="0.85")
            ax.axvline(z_clamp, color="k", lw=1)
            ax.set_xlim(z_end, 0)
            ax.text(z_clamp, 365, " clamp edge", fontsize=7, va="bottom")
            ax.set_ylim(0, 360)
            ax.set_yticks([0, 90, 180, 270, 360])
            ax.set_ylabel(f"layers {a}-{b}\nangle (deg)", fontsize=8)
            ax.legend(fontsize=7, loc="upper right", ncol=4)
            ax.grid(alpha=0.3)
        axes[-1][0].set_xlabel("axial position from midspan (mm)")
        fig.suptitle("contact status at the first peak load (slipping: stuck earlier in the loading)", fontsize=9)
        written.append(save_figure(fig, os.path.join(folder, "bending_status_maps.png")))
    return written


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    for folder in sys.argv[1:]:
        for path in plot_folder(folder):
            print(path)
