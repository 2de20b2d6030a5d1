#!/usr/bin/python3
"""Rebuilds the figures of docs/: for every PNG there, the cases or sweeps it comes from and the plot that draws it.

  scripts/docs_figures.py --list                    one line per figure: its cost, its runs, its plot
  scripts/docs_figures.py --check                   fails if a PNG of docs/ has no entry, or an entry names a case
                                                    file or plot script that does not exist (runs nothing)
  scripts/docs_figures.py --only NAME [NAME ...]    rebuild these figures (names with or without .png, or patterns
                                                    such as 'validation_cardinal_fig19*')
  scripts/docs_figures.py --all                     rebuild every figure

Runs go into --results DIR (default ./figure-runs), one folder per run or sweep; a folder that holds a finished run
(summary.json converged, or a sweep.csv whose variants all ended with exit code 0) is used as it is. The figures are
written into docs/ (or --out DIR). Every command is printed before it runs; --dry-run prints them only.

Cost, from the wall times the docs give for these runs on 2 cores: fast (under a minute), minutes (under half an
hour), long (more); "not stated" where the docs give none.

Where the docs say a figure was drawn from a run with numerical keys (contact.normal_smoothing, the solver's
stabilization and line search) or with more cycles, the run here is `strandfem sweep` of the shipped case with
those keys set (--set), so that the figure shows the run the text describes.
"""
import argparse
import csv
import fnmatch
import json
import os
import shlex
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = os.path.join(ROOT, "docs")
BENDING = "cases/paper/bending/"
LOAD_POINT = "cases/studies/load_point/"
# The solver's keys of the bending runs in docs/validation/bending.md and docs/performance.md, as a whole map: the
# cases it is set on have no solver map of their own.
SPRING = "contact.stabilization=1.0e-5"  # the contact spring the mu_a 0.9 runs need to unload (friction-studies.md)
SLAVE_WIRE = "contact.friction_direction=slave_wire"
TWO_CYCLES = "steps.1.cycles=2"
BAND = "contact.normal_smoothing=1.0e-3"  # the onset band of the Fig. 19 grid and the two-cycle studies (friction-studies.md)


def variant_folder_name(key, value):
    """The results folder `strandfem sweep --key` gives a value (src/strandfem/io/case_variant.cpp)."""
    return "".join(c if c.isalnum() or c in "._=-" else "_" for c in f"{key}={value}")


class Job:
    """One strandfem process: `run` of one case as shipped, or `sweep` (several cases, a key over values, or
    settings). wall_s: the wall time the docs give (seconds, all variants), None where they give none."""

    def __init__(self, name, cases, key=None, values=(), sets=(), wall_s=None):
        self.name, self.cases, self.key, self.values, self.sets = name, list(cases), key, list(values), list(sets)
        self.wall_s = wall_s

    @property
    def is_run(self):
        return len(self.cases) == 1 and not self.key and not self.sets

    def variants(self):
        if self.key:
            return [variant_folder_name(self.key, v) for v in self.values]
        names = []
        for case in self.cases:
            name = os.path.splitext(os.path.basename(case))[0]
            if name in names:
                name += f"_{len(names) + 1}"  # as strandfem sweep names a repeated file name
            names.append(name)
        return names

    def folder(self, results, variant=None):
        """The results folder of the run, or of one variant of the sweep (its only one by default)."""
        base = os.path.join(results, self.name)
        if self.is_run:
            return base
        if variant is None:
            variant = self.variants()[0]
        return os.path.join(base, variant)

    def describe(self):
        words = ["run" if self.is_run else "sweep"] + self.cases
        if self.key:
            words += ["--key", self.key, "--values", ",".join(self.values)]
        for setting in self.sets:
            words += ["--set", setting]
        return shlex.join(words)

    def command(self, strandfem, results, threads, quiet):
        words = [strandfem, "run" if self.is_run else "sweep"] + [os.path.join(ROOT, c) for c in self.cases]
        if self.key:
            words += ["--key", self.key, "--values", ",".join(self.values)]
        for setting in self.sets:
            words += ["--set", setting]
        words += ["-o", os.path.join(results, self.name)]
        if threads:
            words += ["-t", str(threads)]
        if quiet:
            words.append("-q")
        return words

    def finished(self, results):
        folder = os.path.join(results, self.name)
        if self.is_run:
            try:
                with open(os.path.join(folder, "summary.json")) as f:
                    return json.load(f).get("status") == "converged"
            except (OSError, ValueError):
                return False
        try:
            with open(os.path.join(folder, "sweep.csv")) as f:
                rows = list(csv.DictReader(f))
        except OSError:
            return False
        return [r["variant"] for r in rows] == self.variants() and all(r["exit_code"] == "0" for r in rows)


def run_job(name, case, wall_s=None):
    return Job(name, [case], wall_s=wall_s)


# Walls from the docs, in seconds, with where they are given.
JOBS = {j.name: j for j in [
    # Section 3.1, elastoplastic wires: plot_plasticity.py reads RUNS/seven_fixed, seven_free and wire_120.
    run_job("plasticity/seven_fixed", "cases/paper/seven_wire_plastic_fixed.yaml"),
    run_job("plasticity/seven_free", "cases/paper/seven_wire_plastic_free.yaml", 55),  # validation/default-settings.md
    run_job("plasticity/wire_120", "cases/paper/wire_120_plastic.yaml", 710),  # validation.md
    # Section 3.2, S32, as shipped.
    run_job("s32_case1", BENDING + "s32_case1.yaml", 362),  # validation/bending.md, alone
    run_job("s32_case2", BENDING + "s32_case2.yaml", 352),  # validation.md
    run_job("s32_case3", BENDING + "s32_case3.yaml", 338),  # validation.md
    run_job("s32_case4", BENDING + "s32_case4.yaml", 1514),  # validation/bending.md, alone
    # Section 4, Cardinal: fig9 and the maps as shipped.
    run_job("cardinal_fig9", BENDING + "cardinal_fig9.yaml", 2113),  # validation.md, beside another run
    run_job("cardinal_maps", BENDING + "cardinal_maps.yaml", 759),  # performance.md, one thread beside another run
    # Section 5, first loops (one cycle): the sweeps of the cardinal_friction*.yaml headers.
    Job("fig15_mu_a", [BENDING + "cardinal_friction.yaml"], key="contact.friction", values=["0.5", "0.7", "0.9"],
        wall_s=1159 + 1131 + 7200),  # validation/default-settings.md, one thread beside other runs
    Job("fig17_zones", [BENDING + "cardinal_friction.yaml", BENDING + "cardinal_zones_07_03.yaml",
                        BENDING + "cardinal_zones_09_01.yaml"]),  # the same; one of the three walls is not given
    Job("fig19a_strand_axis", [BENDING + "cardinal_friction.yaml"], key="contact.orthotropy_ratio",
        values=["1", "5", "10", "15"], sets=[BAND], wall_s=178 + 234 + 336 + 279),  # validation/friction-studies.md
    Job("fig19b_strand_axis", [BENDING + "cardinal_friction_mu07.yaml"], key="contact.orthotropy_ratio",
        values=["1", "5", "10", "15"], sets=[BAND], wall_s=257 + 284 + 261 + 365),  # the same
    Job("fig19c_strand_axis", [BENDING + "cardinal_friction_mu09.yaml"], key="contact.orthotropy_ratio",
        values=["1", "5", "10", "15"], sets=[BAND], wall_s=241 + 262 + 323 + 396),  # the same
    Job("fig19a_slave_wire", [BENDING + "cardinal_friction.yaml"], key="contact.orthotropy_ratio",
        values=["1", "5", "10", "15"], sets=[SLAVE_WIRE, BAND], wall_s=215 + 304 + 381 + 498),  # the same
    Job("fig19b_slave_wire", [BENDING + "cardinal_friction_mu07.yaml"], key="contact.orthotropy_ratio",
        values=["1", "5", "10", "15"], sets=[SLAVE_WIRE, BAND], wall_s=269 + 325 + 540 + 1025),  # the same
    Job("fig19c_slave_wire", [BENDING + "cardinal_friction_mu09.yaml"], key="contact.orthotropy_ratio",
        values=["1", "5", "10", "15"], sets=[SLAVE_WIRE, SPRING, BAND], wall_s=328 + 446 + 896 + 1992),  # the same
    # Section 5, two cycles: validation/friction-studies.md, "The return loops".
    Job("mu05_two_cycles", [BENDING + "cardinal_friction.yaml"], sets=[TWO_CYCLES, BAND], wall_s=401),
    Job("mu07_two_cycles", [BENDING + "cardinal_friction_mu07.yaml"], sets=[TWO_CYCLES, BAND], wall_s=479),
    Job("mu09_two_cycles", [BENDING + "cardinal_friction_mu09.yaml"], sets=[TWO_CYCLES, SPRING, BAND], wall_s=545),
    Job("zones_two_cycles", [BENDING + "cardinal_zones_07_03.yaml", BENDING + "cardinal_zones_09_01.yaml"],
        sets=[TWO_CYCLES, BAND], wall_s=395 + 451),
    Job("mu05_slave_wire_two_cycles", [BENDING + "cardinal_friction.yaml"], key="contact.orthotropy_ratio",
        values=["5", "15"], sets=[SLAVE_WIRE, TWO_CYCLES, BAND], wall_s=578 + 979),
    Job("mu07_slave_wire_two_cycles", [BENDING + "cardinal_friction_mu07.yaml"], key="contact.orthotropy_ratio",
        values=["5"], sets=[SLAVE_WIRE, TWO_CYCLES, BAND], wall_s=624),
    Job("mu09_slave_wire_two_cycles", [BENDING + "cardinal_friction_mu09.yaml"], key="contact.orthotropy_ratio",
        values=["5"], sets=[SLAVE_WIRE, TWO_CYCLES, SPRING, BAND], wall_s=826),
    # The curve from the load point (validation/bending.md): no walls given.
] + [run_job("load_point/" + name, LOAD_POINT + name + ".yaml") for name in (
    "s32_case1_core", "s32_case1_section", "s32_case1_saddle45", "s32_case1_saddle90", "s32_case1_saddle150",
    "s32_case2_core", "s32_case2_saddle150", "s32_case3_core", "s32_case3_saddle90",
    "s32_case4_core", "s32_case4_saddle90", "s32_case4_saddle150",
    "cardinal_core", "cardinal_saddle90", "cardinal_saddle150")]}


class Plot:
    """A plot command and where the figure it draws lands; one command may draw several figures."""

    script = ""
    wall_s = None  # the docs' wall time of the cases the plot script runs itself

    def jobs(self):
        return []

    def cases(self):
        """Case files the plot script runs itself."""
        return []

    def command(self, figure, args):
        raise NotImplementedError

    def drawn(self, figure, args):
        """The PNG the command writes for this figure, to be copied to the output folder (None: written there)."""
        return None

    def prepare(self, figure, args):
        """Work before the command (a merged sweep table); a line to print, or None."""
        return None


class BendingPlot(Plot):
    """scripts/plot_bending.py on one results folder; `image` is one of the PNGs it writes there."""

    script = "scripts/plot_bending.py"

    def __init__(self, job, image):
        self.job, self.image = job, image

    def jobs(self):
        return [self.job]

    def command(self, figure, args):
        return [sys.executable, os.path.join(ROOT, self.script), JOBS[self.job].folder(args.results)]

    def drawn(self, figure, args):
        return os.path.join(JOBS[self.job].folder(args.results), self.image)


class SweepPlot(Plot):
    """scripts/plot_sweep.py on a sweep folder for this figure whose sweep.csv lists the variants of one or more
    sweeps (job, variant, legend label): it can put runs with different settings on one figure."""

    script = "scripts/plot_sweep.py"

    def __init__(self, *sources):
        self.sources = sources

    def jobs(self):
        return list(dict.fromkeys(job for job, _, _ in self.sources))

    def folder(self, figure, args):
        return os.path.join(args.results, os.path.splitext(figure)[0])

    def prepare(self, figure, args):
        folder = self.folder(figure, args)
        table = os.path.join(folder, "sweep.csv")
        if not args.dry_run:
            os.makedirs(folder, exist_ok=True)
            rows = []
            for job, variant, label in self.sources:
                with open(os.path.join(args.results, job, "sweep.csv")) as f:
                    row = next(r for r in csv.DictReader(f) if r["variant"] == variant)
                row["variant"] = label
                row["results"] = os.path.relpath(JOBS[job].folder(args.results, variant), folder)
                rows.append(row)
            with open(table, "w", newline="") as f:
                writer = csv.DictWriter(f, fieldnames=list(rows[0]))
                writer.writeheader()
                writer.writerows(rows)
        return f"# write {table}: " + "; ".join(f"{label} = {job}/{variant}" for job, variant, label in self.sources)

    def command(self, figure, args):
        return [sys.executable, os.path.join(ROOT, self.script), self.folder(figure, args)]

    def drawn(self, figure, args):
        return os.path.join(self.folder(figure, args), "sweep.png")


class ScriptPlot(Plot):
    """A plot script that writes its figures into the output folder itself. `arguments` builds its arguments from
    the options; `runs_cases`: the case files it runs itself (with --strandfem), which the docs time at wall_s."""

    def __init__(self, script, arguments, jobs=(), runs_cases=(), wall_s=None):
        self.script, self.arguments, self._jobs, self._cases = script, arguments, list(jobs), list(runs_cases)
        self.wall_s = wall_s

    def jobs(self):
        return self._jobs

    def cases(self):
        return self._cases

    def command(self, figure, args):
        return [sys.executable, os.path.join(ROOT, self.script)] + self.arguments(figure, args)


VALIDATION = ScriptPlot("scripts/plot_validation.py", lambda figure, a: [a.strandfem, a.out],
                        runs_cases=["cases/paper/seven_wire_fixed.yaml", "cases/paper/seven_wire_free.yaml"],
                        wall_s=0.9 + 20.8)  # performance.md; validation/default-settings.md
VERIFICATION = ScriptPlot("scripts/plot_verification.py", lambda figure, a: [a.strandfem, a.out],
                          runs_cases=["cases/verification/cantilever_roll_up.yaml",
                                      "cases/examples/seven_wire_axial.yaml"])
PLASTICITY = ScriptPlot("scripts/plot_plasticity.py", lambda figure, a: [os.path.join(a.results, "plasticity"), a.out],
                        jobs=["plasticity/seven_fixed", "plasticity/seven_free", "plasticity/wire_120"])
LOAD_POINT_PLOT = ScriptPlot(
    "scripts/plot_load_point.py",
    lambda figure, a: [os.path.join(a.results, "load_point"), "-o", os.path.join(a.out, figure)],
    jobs=sorted(name for name in JOBS if name.startswith("load_point/")))


def sweep_of(job, labels):
    """Every variant of one sweep, with these legend labels in its order."""
    return SweepPlot(*[(job, variant, label) for variant, label in zip(JOBS[job].variants(), labels)])


RATIOS = ["μ2/μ1 = 1", "μ2/μ1 = 5", "μ2/μ1 = 10", "μ2/μ1 = 15"]

FIGURES = {
    # Verification (docs/verification.md): the plot script runs its two cases itself.
    "verification_rollup.png": VERIFICATION,
    "verification_seven_wire.png": VERIFICATION,
    # Section 3.1.
    "validation_seven_wire.png": VALIDATION,
    "validation_plasticity.png": PLASTICITY,
    "validation_wire_120_von_mises.png": PLASTICITY,
    # Section 3.2, S32.
    "validation_s32_case1_deflection.png": BendingPlot("s32_case1", "bending_deflection.png"),
    "validation_s32_case2_hysteresis.png": BendingPlot("s32_case2", "bending_hysteresis.png"),
    "validation_s32_case2_deflection.png": BendingPlot("s32_case2", "bending_deflection.png"),
    "validation_s32_case3_hysteresis.png": BendingPlot("s32_case3", "bending_hysteresis.png"),
    "validation_s32_case3_deflection.png": BendingPlot("s32_case3", "bending_deflection.png"),
    "validation_s32_case4_five_cycles.png": BendingPlot("s32_case4", "bending_hysteresis.png"),
    "validation_bending_from_load_point.png": LOAD_POINT_PLOT,
    # Section 4, Cardinal.
    "validation_cardinal_fig9_hysteresis.png": BendingPlot("cardinal_fig9", "bending_hysteresis.png"),
    "validation_cardinal_fig9_deflection.png": BendingPlot("cardinal_fig9", "bending_deflection.png"),
    "validation_cardinal_fig9_status_maps.png": BendingPlot("cardinal_fig9", "bending_status_maps.png"),
    "validation_cardinal_fig9_contact_forces.png": BendingPlot("cardinal_fig9",
                                                               "bending_contact_forces.png"),
    "validation_cardinal_maps_hysteresis.png": BendingPlot("cardinal_maps", "bending_hysteresis.png"),
    "validation_cardinal_maps_status_maps.png": BendingPlot("cardinal_maps", "bending_status_maps.png"),
    # Section 5, first loops.
    "validation_cardinal_fig15.png": sweep_of("fig15_mu_a", ["μa 0.5", "μa 0.7", "μa 0.9"]),
    "validation_cardinal_fig17_radial.png": sweep_of(
        "fig17_zones", ["μa 0.5", "zones 0.7 / 0.3, radial", "zones 0.9 / 0.1, radial"]),
    "validation_cardinal_fig19a.png": sweep_of("fig19a_strand_axis", RATIOS),
    "validation_cardinal_fig19b.png": sweep_of("fig19b_strand_axis", RATIOS),
    "validation_cardinal_fig19c.png": sweep_of("fig19c_strand_axis", RATIOS),
    "validation_cardinal_fig19a_slave_wire.png": sweep_of("fig19a_slave_wire", RATIOS),
    "validation_cardinal_fig19b_slave_wire.png": sweep_of("fig19b_slave_wire", RATIOS),
    "validation_cardinal_fig19c_slave_wire.png": sweep_of("fig19c_slave_wire", RATIOS),
    # Section 5, two cycles (return loops).
    "validation_cardinal_fig15_return_loops.png": SweepPlot(
        ("mu05_two_cycles", "cardinal_friction", "μa 0.5"),
        ("mu07_two_cycles", "cardinal_friction_mu07", "μa 0.7"),
        ("mu09_two_cycles", "cardinal_friction_mu09", "μa 0.9 (contact.stabilization 1e-5)")),
    "validation_cardinal_fig17_return_loops.png": SweepPlot(
        ("mu05_two_cycles", "cardinal_friction", "μa 0.5"),
        ("zones_two_cycles", "cardinal_zones_07_03", "zones 0.7 / 0.3, radial"),
        ("zones_two_cycles", "cardinal_zones_09_01", "zones 0.9 / 0.1, radial")),
    "validation_cardinal_fig19a_return_loops.png": SweepPlot(
        ("mu05_two_cycles", "cardinal_friction", "μa 0.5, μ2/μ1 = 1"),
        ("mu05_slave_wire_two_cycles", variant_folder_name("contact.orthotropy_ratio", "5"), "μa 0.5, μ2/μ1 = 5"),
        ("mu05_slave_wire_two_cycles", variant_folder_name("contact.orthotropy_ratio", "15"), "μa 0.5, μ2/μ1 = 15")),
    "validation_cardinal_fig19bc_return_loops.png": SweepPlot(
        ("mu07_two_cycles", "cardinal_friction_mu07", "μa 0.7, μ2/μ1 = 1"),
        ("mu07_slave_wire_two_cycles", variant_folder_name("contact.orthotropy_ratio", "5"), "μa 0.7, μ2/μ1 = 5"),
        ("mu09_two_cycles", "cardinal_friction_mu09", "μa 0.9, μ2/μ1 = 1 (contact.stabilization 1e-5)"),
        ("mu09_slave_wire_two_cycles", variant_folder_name("contact.orthotropy_ratio", "5"),
         "μa 0.9, μ2/μ1 = 5 (contact.stabilization 1e-5)")),
}


def cost(plot):
    """The cost class from the docs' wall times of the figure's runs (those the docs time)."""
    walls = [JOBS[j].wall_s for j in plot.jobs() if JOBS[j].wall_s is not None]
    if plot.wall_s is not None:
        walls.append(plot.wall_s)
    if not walls:
        return "not stated"
    total = sum(walls)
    return "fast" if total < 60 else "minutes" if total < 1800 else "long"


def sources(plot):
    """What --list says a figure comes from."""
    if isinstance(plot, ScriptPlot) and plot.cases():
        return "the plot script runs " + ", ".join(plot.cases())
    jobs = [JOBS[j] for j in plot.jobs()]
    if len(jobs) > 3 and all(j.is_run for j in jobs):
        folders = sorted({os.path.dirname(j.cases[0]) for j in jobs})
        return f"run each of {len(jobs)} cases in " + ", ".join(f + "/" for f in folders)
    return "; ".join(j.describe() for j in jobs)


def check():
    """Problems of the table against the tree: figures without an entry, entries without a figure, missing case
    files or plot scripts, sweep variants no job makes."""
    problems = []
    present = sorted(f for f in os.listdir(DOCS) if f.endswith(".png"))
    for figure in present:
        if figure not in FIGURES:
            problems.append(f"docs/{figure} has no entry in scripts/docs_figures.py (FIGURES)")
    for figure in FIGURES:
        if figure not in present:
            problems.append(f"scripts/docs_figures.py has an entry for docs/{figure}, which does not exist")
    for figure, plot in FIGURES.items():
        if not os.path.isfile(os.path.join(ROOT, plot.script)):
            problems.append(f"{figure}: plot script {plot.script} does not exist")
        for case in plot.cases():
            if not os.path.isfile(os.path.join(ROOT, case)):
                problems.append(f"{figure}: case file {case} does not exist")
        for job in plot.jobs():
            if job not in JOBS:
                problems.append(f"{figure}: no run or sweep named {job}")
        if isinstance(plot, SweepPlot):
            for job, variant, _ in plot.sources:
                if job in JOBS and variant not in JOBS[job].variants():
                    problems.append(f"{figure}: {job} makes no variant {variant} (it makes {JOBS[job].variants()})")
    for job in JOBS.values():
        for case in job.cases:
            if not os.path.isfile(os.path.join(ROOT, case)):
                problems.append(f"run {job.name}: case file {case} does not exist")
    return problems, len(present)


def select(names):
    chosen = []
    for name in names:
        name = os.path.basename(name)
        pattern = name if name.endswith(".png") or any(c in name for c in "*?[") else name + ".png"
        matches = [f for f in FIGURES if fnmatch.fnmatch(f, pattern) or fnmatch.fnmatch(f, pattern + ".png")]
        if not matches:
            sys.exit(f"docs_figures.py: no figure matches '{name}' (--list shows them)")
        chosen += [m for m in matches if m not in chosen]
    return chosen


def show(words):
    print("+ " + shlex.join(words), flush=True)


def build(figures, args):
    """Runs what the figures need that is not finished in args.results, then their plots; False if any failed."""
    done_jobs, failed_jobs, done_plots = set(), set(), {}
    ok = True
    for figure in figures:
        plot = FIGURES[figure]
        for name in plot.jobs():
            if name in done_jobs or name in failed_jobs:
                continue
            job = JOBS[name]
            if job.finished(args.results):
                print(f"# {os.path.join(args.results, name)}: finished, used as it is", flush=True)
                done_jobs.add(name)
                continue
            words = job.command(args.strandfem, args.results, args.threads, args.quiet)
            show(words)
            if args.dry_run:
                done_jobs.add(name)
                continue
            os.makedirs(os.path.dirname(os.path.join(args.results, name)) or ".", exist_ok=True)
            code = subprocess.call(words)
            if code != 0:
                print(f"docs_figures.py: {name} failed (exit code {code})", file=sys.stderr)
                failed_jobs.add(name)
            else:
                done_jobs.add(name)
        missing = [j for j in plot.jobs() if j in failed_jobs]
        if missing:
            print(f"docs_figures.py: {figure} not drawn: {', '.join(missing)} failed", file=sys.stderr)
            ok = False
            continue
        note = plot.prepare(figure, args)
        if note:
            print(note, flush=True)
        words = plot.command(figure, args)
        key = tuple(words)
        if key not in done_plots:
            show(words)
            done_plots[key] = 0 if args.dry_run else subprocess.call(words)
        if done_plots[key] != 0:
            print(f"docs_figures.py: {figure} not drawn: the plot command failed", file=sys.stderr)
            ok = False
            continue
        drawn = plot.drawn(figure, args)
        target = os.path.join(args.out, figure)
        if drawn is not None and os.path.abspath(drawn) != os.path.abspath(target):
            show(["cp", drawn, target])
            if not args.dry_run:
                shutil.copyfile(drawn, target)
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    action = parser.add_mutually_exclusive_group(required=True)
    action.add_argument("--list", action="store_true", help="one line per figure: its cost, its runs, its plot")
    action.add_argument("--check", action="store_true", help="check the table against docs/ and cases/ (runs nothing)")
    action.add_argument("--only", nargs="+", metavar="NAME", help="rebuild these figures")
    action.add_argument("--all", action="store_true", help="rebuild every figure")
    parser.add_argument("--results", default="figure-runs", help="folder of the runs (default ./figure-runs)")
    parser.add_argument("--out", default=DOCS, help="folder the figures are written into (default docs/)")
    parser.add_argument("--strandfem", help="the program (default build/apps/strandfem, else strandfem on PATH)")
    parser.add_argument("-t", "--threads", type=int, default=0, help="threads per run (strandfem -t; 0: its default)")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress lines from the runs")
    parser.add_argument("--dry-run", action="store_true", help="print the commands only")
    args = parser.parse_args()

    if args.check:
        problems, count = check()
        for problem in problems:
            print("docs_figures.py --check: " + problem, file=sys.stderr)
        if problems:
            return 1
        print(f"docs_figures.py --check: {count} figures in docs/, each with its runs and plot script present")
        return 0
    if args.list:
        for figure, plot in FIGURES.items():
            print(f"{figure:46} {cost(plot):10} {sources(plot)} -> {plot.script}")
        return 0

    if not args.strandfem:
        built = os.path.join(ROOT, "build", "apps", "strandfem")
        args.strandfem = built if os.path.exists(built) else shutil.which("strandfem") or "strandfem"
    if not args.dry_run and shutil.which(args.strandfem) is None and not os.access(args.strandfem, os.X_OK):
        sys.exit(f"docs_figures.py: no strandfem at {args.strandfem} (build it, or give --strandfem PATH)")
    args.results = os.path.abspath(args.results)
    args.out = os.path.abspath(args.out)
    if not args.dry_run:
        os.makedirs(args.results, exist_ok=True)
        os.makedirs(args.out, exist_ok=True)
    figures = list(FIGURES) if args.all else select(args.only)
    return 0 if build(figures, args) else 1


if __name__ == "__main__":
    sys.exit(main())
