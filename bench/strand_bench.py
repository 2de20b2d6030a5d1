#!/usr/bin/python3
"""Runs strand cases through `strandfem run` and prints, per case: convergence, wall time, increments, Newton
iterations, factorizations, GMRES iterations, time in assembly and linear solves, the ordering that actually ran,
factor entries and flops, and the axial slope against the fixed-end linear strand theory.

    bench/strand_bench.py [--program build/apps/strandfem] [--frictionless] [--threads N] [--processes P]
                          [--set solver.extrapolate=false ...] CASE.yaml ...

--frictionless also runs each case with contact.friction (and its pairs and zones) set to 0, so that the
effect of friction on the slope and the cost shows beside it. --set overrides a case key (dotted path, YAML
value) in every run. --processes P runs each case under `mpiexec --bind-to none -np P` (the MPI build of MUMPS:
P processes factor). Results go to a temporary folder per run.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

import yaml


def modified_copy(path, folder, overrides, frictionless):
    with open(path) as f:
        case = yaml.safe_load(f)
    for key, value in overrides:
        node = case
        *parents, leaf = key.split(".")
        for name in parents:
            node = node.setdefault(name, {})
        node[leaf] = value
    if frictionless:
        contact = case.setdefault("contact", {})
        contact["friction"] = 0.0
        contact.pop("friction_pairs", None)
        contact.pop("friction_zones", None)
    out = os.path.join(folder, ("frictionless_" if frictionless else "") + os.path.basename(path))
    with open(out, "w") as f:
        yaml.safe_dump(case, f)
    return out


def run(program, case, threads, processes, folder):
    out = os.path.join(folder, "results")
    command = [program, "run", case, "-o", out, "-q"] + (["-t", str(threads)] if threads else [])
    if processes > 1:
        command = ["mpiexec", "--allow-run-as-root", "--bind-to", "none", "-np", str(processes)] + command
    start = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True)
    wall = time.monotonic() - start
    info = json.loads(subprocess.run([program, "info", case], capture_output=True, text=True, check=True).stdout)
    row = {"case": os.path.basename(case), "exit": result.returncode, "wall_s": round(wall, 1)}
    history = os.path.join(out, "history.csv")
    rows = list(csv.DictReader(open(history))) if os.path.exists(history) else []
    row["increments"] = len(rows)
    if rows:
        last = rows[-1]
        strain, force = float(last["axial_strain"]), float(last["axial_force_N"])
        theory = info.get("axial_stiffness_N", {}).get("fixed_ends")
        if strain and theory:
            row["slope_MN"] = round(force / strain / 1e6, 3)
            row["theory_MN"] = round(theory / 1e6, 3)
            row["slope_vs_theory_%"] = round(100 * (force / strain / theory - 1), 2)
    summary = os.path.join(out, "summary.json")
    if os.path.exists(summary):
        summary_json = json.load(open(summary))
        s = summary_json.get("solver_statistics", {})
        row["instruction_set"] = summary_json.get("build", {}).get("instruction_set")
        row.update({k: s.get(k) for k in ("newton_iterations", "factorizations", "krylov_solves", "krylov_iterations", "pattern_rebuilds", "rejected_extrapolations", "plain_retries", "limited_corrections", "double_precision_fallbacks", "force_only_acceptances",
                                          "assembly_seconds", "residual_seconds", "commit_seconds", "linear_seconds", "pattern_seconds", "factorization_seconds", "analysis_seconds", "ordering",
                                          "blas_kernels", "mumps_processes", "factor_entries", "factorization_flops")})
        for k in row:
            if k.endswith("_seconds") and row[k] is not None:
                row[k] = round(row[k], 1)
        if row.get("newton_iterations"):
            row["s_per_iteration"] = round(wall / row["newton_iterations"], 2)
    if result.returncode != 0:
        row["message"] = result.stderr.strip().splitlines()[-2:] if result.stderr else ""
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cases", nargs="+")
    parser.add_argument("--program", default=os.path.join(os.path.dirname(__file__), "..", "build", "apps", "strandfem"))
    parser.add_argument("--frictionless", action="store_true")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--processes", type=int, default=1, help="MUMPS processes (mpiexec -np), MPI build only")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="override a case key in every run, e.g. solver.extrapolate=false")
    args = parser.parse_args()
    overrides = []
    for item in args.set:
        key, _, value = item.partition("=")
        overrides.append((key, yaml.safe_load(value)))
    for case in args.cases:
        with tempfile.TemporaryDirectory() as folder:
            variants = [("friction", modified_copy(case, folder, overrides, False) if overrides else case)]
            if args.frictionless:
                variants.append(("frictionless", modified_copy(case, folder, overrides, True)))
            for label, path in variants:
                with tempfile.TemporaryDirectory() as run_folder:
                    row = run(args.program, path, args.threads, args.processes, run_folder)
                row["variant"] = label
                print(json.dumps(row), flush=True)


if __name__ == "__main__":
    sys.exit(main())
