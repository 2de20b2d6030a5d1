#!/usr/bin/python3
"""Runs paper cases on every combination of build, thread count and MUMPS process count, and prints one Markdown
table row per run: whether it reached its end, its wall time, and what it measured (the last axial force and
strain; for bending, each cycle's peak deflection and loop area). Whether a run ends must not depend on the path
round-off takes, so every row of one case should read "ends".

    scripts/machine_matrix.py --program v3=build/apps/strandfem --program generic=build-generic/apps/strandfem
                              [--threads 1 2] [--processes 1 2] [--only NAME ...] [--out matrix.md] [CASE.yaml ...]

A generic build: `cmake -S . -B build-generic -G Ninja -DCMAKE_BUILD_TYPE=Release -DSTRANDFEM_X86_64_V3=OFF`.
Without CASE arguments it runs the default list below (several hours on 2 cores: run it in parts with --only).
Each run writes to a temporary folder; --out appends the rows to a file as they come.
"""
import argparse
import csv
import itertools
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_CASES = [
    "cases/paper/axial/strand_19.yaml",
    "cases/paper/axial/strand_37.yaml",
    "cases/paper/axial/s32_200.yaml",
    "cases/paper/axial/s32_1m.yaml",
    "cases/paper/axial/cardinal_200.yaml",
    "cases/paper/axial/cardinal_1m.yaml",
    "cases/paper/axial/wire_120.yaml",
    "cases/paper/seven_wire_plastic_fixed.yaml",
    "cases/paper/wire_120_plastic.yaml",
    "cases/paper/bending/s32_case1.yaml",
    "cases/paper/bending/cardinal_maps.yaml",
]


def measured(out):
    """What a run measured, from its results folder."""
    summary_path = os.path.join(out, "summary.json")
    summary = json.load(open(summary_path)) if os.path.exists(summary_path) else {}
    loops = summary.get("bending", {}).get("loops", [])
    if loops:
        return "; ".join(f"cycle {l['cycle']}: peak {l['peak_deflection_mm']:.4g} mm, loop {l['area_Nmm'] / 1000:.4g} N m"
                         for l in loops)
    history = os.path.join(out, "history.csv")
    rows = list(csv.DictReader(open(history))) if os.path.exists(history) else []
    if not rows:
        return "no increment"
    last = rows[-1]
    return f"strain {float(last['axial_strain']):.5g}, force {float(last['axial_force_N']) / 1000:.5g} kN"


def run(program, case, threads, processes, keep=None, label=""):
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(keep, label) if keep else os.path.join(folder, "results")
        command = [program, "run", case, "-o", out, "-q", "-t", str(threads)]
        if processes > 1:
            command = ["mpiexec", "--allow-run-as-root", "--bind-to", "none", "-np", str(processes)] + command
        start = time.monotonic()
        code = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
        wall = time.monotonic() - start
        status = {0: "ends", 3: "stops (did not converge)"}.get(code, f"exit {code}")
        return status, wall, measured(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cases", nargs="*")
    parser.add_argument("--program", action="append", default=[], help="NAME=PATH of a strandfem build")
    parser.add_argument("--threads", nargs="+", type=int, default=[1, 2])
    parser.add_argument("--processes", nargs="+", type=int, default=[1, 2])
    parser.add_argument("--only", nargs="+", default=[], help="run only cases whose file name contains one of these")
    parser.add_argument("--out", help="append the table rows to this file")
    parser.add_argument("--keep", help="write each run's results folder under this folder (CASE_BUILD_tT_pP) instead of "
                                       "a temporary one, e.g. to draw figures from it")
    args = parser.parse_args()
    programs = [p.split("=", 1) for p in args.program] or [["build", os.path.join(ROOT, "build/apps/strandfem")]]
    cases = args.cases or [os.path.join(ROOT, c) for c in DEFAULT_CASES]
    if args.only:
        cases = [c for c in cases if any(o in os.path.basename(c) for o in args.only)]
    header = "| case | build | threads | processes | status | wall (s) | measured |\n|---|---|---|---|---|---|---|"
    print(header, flush=True)
    if args.out and not os.path.exists(args.out):
        open(args.out, "w").write(header + "\n")
    for case, (name, program), threads, processes in itertools.product(cases, programs, args.threads, args.processes):
        if processes > 1 and threads > 1:
            continue  # two processes run one BLAS thread each on a 2-core machine
        label = f"{os.path.splitext(os.path.basename(case))[0]}_{name}_t{threads}_p{processes}"
        status, wall, result = run(program, case, threads, processes, args.keep, label)
        row = f"| {os.path.basename(case)} | {name} | {threads} | {processes} | {status} | {wall:.0f} | {result} |"
        print(row, flush=True)
        if args.out:
            open(args.out, "a").write(row + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
