"""The Python package against the program's own outputs and the reader's messages (ctest PythonPackage)."""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

import strandfem
from strandfem.case import _yaml_text

SOURCE = os.environ["STRANDFEM_SOURCE_DIR"]
MPIEXEC = os.environ.get("STRANDFEM_MPIEXEC", "")
try:
    import mpi4py  # noqa: F401
    MPI_SWEEP = bool(MPIEXEC)
except ImportError:
    MPI_SWEEP = False
PROGRAM = os.environ["STRANDFEM_BINARY"]


def seven_wire(increments=4, strain=0.004, **contact):
    """The paper's 7-wire strand (Table 1), 100 mm, pulled with fixed ends."""
    return {
        "title": "7-wire strand from Python",
        "materials": {"steel": {"E": 188000, "nu": 0.3}},
        "strand": {"length": 100, "layers": [{"wires": 1, "diameter": 3.94, "material": "steel"},
                                             {"wires": 6, "diameter": 3.73, "material": "steel", "lay_angle": 11.8}]},
        "contact": {"friction": 0.115, **contact},
        "steps": [{"name": "pull", "increments": increments, "axial_strain": strain}],
        "output": {"vtu": False},
    }


class PythonPackage(unittest.TestCase):
    def _interrupted_run(self, case, out, progress):
        """Runs `case` expecting KeyboardInterrupt; returns the folder's results, which must say `stopped`."""
        with self.assertRaises(KeyboardInterrupt):
            case.run(out, threads=1, progress=progress)
        stopped = strandfem.read_results(out)
        self.assertEqual(stopped.status, "stopped")
        return stopped

    def test_version_is_the_programs(self):
        out = subprocess.run([PROGRAM, "--version"], capture_output=True, text=True, check=True).stdout
        self.assertIn(strandfem.__version__, out)

    def test_case_file_info_matches_strandfem_info(self):
        path = os.path.join(SOURCE, "cases/paper/seven_wire_fixed.yaml")
        info = strandfem.Case.from_yaml(path).info()
        program = json.loads(subprocess.run([PROGRAM, "info", path], capture_output=True, text=True, check=True).stdout)
        for key in ("EI_max_Nm2", "EI_min_Nm2", "axial_stiffness_N", "nodes", "dofs"):
            self.assertEqual(info[key], program[key], key)

    def test_bad_key_names_key_and_place(self):
        data = seven_wire()
        data["contact"]["frction"] = 0.2
        with self.assertRaises(strandfem.CaseError) as caught:
            strandfem.Case.from_dict(data, name="my_strand")
        message = str(caught.exception)
        self.assertIn("frction", message)
        line = int(message.split(":")[1])  # my_strand:LINE:COLUMN: ...
        self.assertIn("frction", _yaml_text(data).splitlines()[line - 1])

    def test_case_built_from_objects_is_the_case_from_data(self):
        steel = strandfem.Material("steel", E=188000, nu=0.3)
        strand = strandfem.Strand(length=100, layers=[strandfem.Layer(1, 3.94, steel),
                                                      strandfem.Layer(6, 3.73, steel, lay_angle=11.8)])
        built = strandfem.Case.build(strand, [strandfem.Step("pull", 4, axial_strain=0.004)],
                                     title="7-wire strand from Python", contact={"friction": 0.115}, output={"vtu": False})
        self.assertEqual(built.to_yaml(), strandfem.Case.from_dict(seven_wire()).to_yaml())

    def test_built_case_is_checked_by_the_reader(self):
        steel = strandfem.Material("steel", E=188000, nu=0.3)
        strand = strandfem.Strand(length=100, layers=[strandfem.Layer(1, 3.94, steel),
                                                      strandfem.Layer(6, 3.73, steel, lay_angle=95)])
        with self.assertRaises(strandfem.CaseError) as caught:
            strandfem.Case.build(strand, [strandfem.Step("pull", 4, axial_strain=0.004)], name="built")
        self.assertIn("lay_angle", str(caught.exception))
        self.assertIn("built:", str(caught.exception))
        other = strandfem.Material("steel", E=70000, nu=0.33)
        with self.assertRaises(ValueError):
            strandfem.Strand(length=100, layers=[strandfem.Layer(1, 3.94, steel), strandfem.Layer(6, 3.73, other, lay_angle=11.8)]).materials()

    def test_missing_file_is_a_case_error(self):
        with self.assertRaises(strandfem.CaseError):
            strandfem.Case.from_yaml(os.path.join(SOURCE, "no_such_case.yaml"))

    def test_run_matches_the_program_and_reads_back(self):
        case = strandfem.Case.from_dict(seven_wire())
        with tempfile.TemporaryDirectory() as folder:
            calls = []
            results = case.run(os.path.join(folder, "py"), threads=1, progress=calls.append)
            self.assertTrue(results.converged, results.message)
            history = results.history
            self.assertEqual(len(history), len(calls))
            self.assertAlmostEqual(calls[-1]["step_fraction"], 1.0)
            self.assertAlmostEqual(history["axial_strain"].iloc[-1], 0.004)
            # The same case through the program gives the same numbers.
            case_file = os.path.join(folder, "case.yaml")
            with open(case_file, "w") as f:
                f.write(case.to_yaml())
            subprocess.run([PROGRAM, "run", case_file, "-o", os.path.join(folder, "cli"), "-q", "-t", "1"], check=True)
            cli = strandfem.read_results(os.path.join(folder, "cli"))
            for a, b in zip(history["axial_force_N"], cli.history["axial_force_N"]):
                self.assertTrue(math.isclose(a, b, rel_tol=1e-9), (a, b))
            self.assertTrue(math.isclose(results.summary["axial"]["axial_force_N"], history["axial_force_N"].iloc[-1],
                                         rel_tol=1e-9))
            self.assertIsNone(results.loops)  # an axial case writes no bending loops

    def test_exception_in_progress_stops_cleanly_and_resume_finishes(self):
        case = strandfem.Case.from_dict(seven_wire(increments=6))
        with tempfile.TemporaryDirectory() as folder:
            full = case.run(os.path.join(folder, "full"), threads=1)

            def stop_at_two(report):
                if report["increment"] == 2:
                    raise KeyboardInterrupt

            out = os.path.join(folder, "stopped")
            self.assertEqual(len(self._interrupted_run(case, out, stop_at_two).history), 2)
            resumed = case.run(out, threads=1, resume=True)
            self.assertTrue(resumed.converged)
            self.assertEqual(len(resumed.history), len(full.history))
            # A resumed run starts its next increment from the plain predictor, so it matches to the solver's
            # tolerance, not bit for bit (as resume_test.cpp's inexact case).
            largest = full.history["axial_force_N"].abs().max()
            for a, b in zip(resumed.history["axial_force_N"], full.history["axial_force_N"]):
                self.assertLess(abs(a - b), 1e-4 * largest)

    def test_references_match_eq_3_1_and_invert(self):
        V, T, EI, L = 500.0, 30000.0, 2.0e7, 300.0
        k = math.sqrt(EI / T)
        y = V / T * (L / 4 - k * math.tanh(L / (4 * k)))  # eq. 3.1, written out
        self.assertTrue(math.isclose(strandfem.references.midspan_deflection(V, T, EI, L), y, rel_tol=1e-12))
        self.assertTrue(math.isclose(strandfem.references.deflection_curve(V, T, EI, L, L / 2), y, rel_tol=1e-9))
        self.assertTrue(math.isclose(strandfem.references.equivalent_bending_stiffness(y / V, T, L), EI, rel_tol=1e-6))
        curve = strandfem.references.deflection_curve(V, T, EI, L, [0.0, L / 4, L / 2])
        self.assertEqual(curve[0], 0.0)
        self.assertLess(curve[1], curve[2])
        refs = strandfem.Case.from_dict(seven_wire()).references()
        self.assertGreater(refs["ei_max_Nm2"], refs["ei_min_Nm2"])
        self.assertGreaterEqual(refs["axial_stiffness_fixed_N"], refs["axial_stiffness_free_N"])

    def test_conductors_are_the_programs_and_a_named_conductor_builds(self):
        table = strandfem.conductors()
        listed = subprocess.run([PROGRAM, "conductors"], capture_output=True, text=True, check=True).stdout.splitlines()
        self.assertEqual(len(table), len(listed) - 1)
        drake = table[table["conductor"] == "Drake"].iloc[0]
        self.assertEqual(drake["wires"], 33)
        self.assertIn(f"{drake['EI_max_Nm2']:.1f}", next(line for line in listed if line.startswith("Drake ")))
        case = strandfem.Case.from_dict({"title": "t", "strand": {"conductor": "drake", "length": 300},
                                         "steps": [{"name": "pull", "increments": 1, "axial_force": 1000}]})
        self.assertAlmostEqual(case.info()["EI_max_Nm2"], drake["EI_max_Nm2"], places=1)
        # Poffenberger-Swart without tension: a cantilever's E d / (2 xb^2) per mm of yb.
        self.assertTrue(math.isclose(strandfem.references.poffenberger_swart_stress(1.0, 1e-9, 4.3e7, 68000, 4.44),
                                     68000 * 4.44 / (2 * 89.0**2), rel_tol=1e-6))

    def test_sweep_of_a_product_of_keys_and_of_a_list_of_cases(self):
        grid = strandfem.product({"contact.friction": [0.1, 0.3], "strand.length": [60, 80]})
        self.assertEqual(grid, [{"contact.friction": 0.1, "strand.length": 60}, {"contact.friction": 0.1, "strand.length": 80},
                                {"contact.friction": 0.3, "strand.length": 60}, {"contact.friction": 0.3, "strand.length": 80}])
        short = strandfem.Case.from_dict(seven_wire(increments=1, strain=0.001), name="short.yaml")
        with tempfile.TemporaryDirectory() as folder:
            table = strandfem.sweep(short, grid[:2], os.path.join(folder, "grid"), processes=1)
            self.assertEqual(list(table["strand.length"]), [60, 80])
            self.assertEqual(list(table["status"]), ["converged"] * 2)
            longer = short.with_values({"strand.length": 150})
            table = strandfem.sweep([short, longer], None, os.path.join(folder, "cases"), processes=1)
            self.assertEqual(list(table["status"]), ["converged"] * 2)
            self.assertEqual([os.path.basename(f) for f in table["folder"]], ["short", "short_2"])
            # The same strain on a longer strand: the same force, each case solved as it is.
            force = list(table["axial_force_N"])
            self.assertLess(abs(force[1] / force[0] - 1), 0.02, force)
            self.assertEqual(strandfem.read_results(table["folder"][1]).summary["strand_length_mm"], 150)
        with self.assertRaises(ValueError):
            strandfem.sweep([short], [0.1], folder, key="contact.friction")

    def test_variant_sets_the_key_and_checks_it(self):
        case = strandfem.Case.from_dict(seven_wire())
        variant = case.with_values({"contact.friction": 0.3, "strand.layers.1.lay_angle": 12.5})
        self.assertIn("0.3", variant.resolved()["case"])
        self.assertEqual(variant.info()["layers"][1]["lay_angle_deg"], 12.5)
        with self.assertRaises(strandfem.CaseError) as caught:
            case.with_values({"contact.friction": -1})
        self.assertIn("contact.friction", str(caught.exception))

    def test_sweep_over_processes_matches_single_runs(self):
        case = strandfem.Case.from_dict(seven_wire(increments=2))
        with tempfile.TemporaryDirectory() as folder:
            table = strandfem.sweep(case, [0.05, 0.3], os.path.join(folder, "sweep"), key="contact.friction", processes=2)
            self.assertEqual(list(table["contact.friction"]), [0.05, 0.3])
            self.assertEqual(list(table["status"]), ["converged", "converged"])
            single = case.with_values({"contact.friction": 0.3}).run(os.path.join(folder, "single"), threads=1)
            self.assertTrue(math.isclose(table["axial_force_N"].iloc[1], single.summary["axial"]["axial_force_N"], rel_tol=1e-7))
            self.assertTrue(os.path.exists(os.path.join(folder, "sweep", "sweep.csv")))

    def test_table_1_strand_built_in_python_has_the_papers_slope(self):
        steel = strandfem.Material("steel", E=188000, nu=0.3)
        strand = strandfem.Strand(length=200, layers=[strandfem.Layer(1, 3.94, steel),
                                                      strandfem.Layer(6, 3.73, steel, lay_angle=11.8)])
        case = strandfem.Case.build(strand, [strandfem.Step("pull", 4, axial_strain=0.004)], title="Table 1",
                                    mesh={"elements_per_wire": 24}, contact={"friction": 0.115}, output={"vtu": False})
        with tempfile.TemporaryDirectory() as folder:
            results = case.run(os.path.join(folder, "t1"), threads=1)
            strain, force = results.arrays("history", "axial_strain", "axial_force_N")
            self.assertEqual(list(force), list(results.history["axial_force_N"]))
            self.assertEqual(sorted(results.arrays("history")), sorted(results.history.columns))
            with self.assertRaises(KeyError):
                results.arrays("history", "no_such_column")
            self.assertIsNone(results.arrays("loops"))  # an axial run writes no loops
            slope = float((strain * force).sum() / (strain * strain).sum())  # least squares through the origin
            self.assertLess(abs(slope / 13.85e6 - 1), 0.01, slope)  # paper Table 1, fixed ends: 13.85 MN

    @unittest.skipUnless(MPI_SWEEP, "needs mpi4py and mpiexec")
    def test_sweep_on_two_mpi_ranks_equals_the_serial_sweep(self):
        data = seven_wire(increments=2)
        script = (
            "import json, sys, strandfem\n"
            f"CASE = {json.dumps(data)!r}\n"
            "t = strandfem.sweep(strandfem.Case.from_dict(json.loads(CASE)), [0.05, 0.2, 0.3], sys.argv[1],\n"
            "                    key='contact.friction', mpi=True)\n"
            "from mpi4py import MPI\n"
            "open(f'{sys.argv[1]}_rows_{MPI.COMM_WORLD.Get_rank()}', 'w').write(str(len(t)))\n")
        with tempfile.TemporaryDirectory() as folder:
            run = _run_under_mpiexec(script, 2, [], os.path.join(folder, "mpi"))
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            self.assertEqual(_per_rank_outputs(os.path.join(folder, "mpi_rows"), 2), ["3", "3"])  # the whole table
            serial = strandfem.sweep(strandfem.Case.from_dict(data), [0.05, 0.2, 0.3], os.path.join(folder, "serial"),
                                     key="contact.friction", processes=1)
            import pandas
            parallel = pandas.read_csv(os.path.join(folder, "mpi", "sweep.csv"))
            self.assertEqual(list(parallel["status"]), ["converged"] * 3)
            for column in ("axial_strain", "axial_force_N", "secant_stiffness_N"):
                for a, b in zip(parallel[column], serial[column]):
                    self.assertTrue(math.isclose(a, b, rel_tol=1e-7), (column, a, b))

    def test_an_mpi_rank_limits_openblas_to_its_threads(self):
        import ctypes
        try:
            openblas = ctypes.CDLL("libopenblas.so.0")
        except OSError:
            self.skipTest("the package is not linked with OpenBLAS")
        from strandfem.sweep import _limit_blas_threads
        before = openblas.openblas_get_num_threads()
        try:
            for threads in (1, 2):
                _limit_blas_threads(threads)
                self.assertEqual(openblas.openblas_get_num_threads(), threads)
        finally:
            openblas.openblas_set_num_threads(before)

    @unittest.skipUnless(MPI_SWEEP, "needs mpi4py and mpiexec")
    def test_mpi_ranks_share_one_queue_of_variants(self):
        # The rank that takes variant 0 stays busy with it for a second; the other takes every variant after it.
        script = (
            "import sys, time\n"
            "from mpi4py import MPI\n"
            "from strandfem.sweep import _shared_queue\n"
            "taken = []\n"
            "for i in _shared_queue(MPI.COMM_WORLD, 6):\n"
            "    taken.append(i)\n"
            "    if i == 0:\n"
            "        time.sleep(1.0)\n"
            "open(f'{sys.argv[1]}_{MPI.COMM_WORLD.Get_rank()}', 'w').write(' '.join(map(str, taken)))\n")
        with tempfile.TemporaryDirectory() as folder:
            run = _run_under_mpiexec(script, 2, [], os.path.join(folder, "queue"))
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            taken = [[int(i) for i in text.split()] for text in _per_rank_outputs(os.path.join(folder, "queue"), 2)]
            self.assertEqual(sorted(taken[0] + taken[1]), list(range(6)), taken)  # each variant once
            busy = 0 if 0 in taken[0] else 1
            self.assertEqual(taken[busy], [0], taken)
            self.assertEqual(taken[1 - busy], [1, 2, 3, 4, 5], taken)

    @unittest.skipUnless(MPI_SWEEP, "needs mpi4py and mpiexec")
    def test_sweep_through_an_mpi4py_pool(self):
        script = (
            "import sys, strandfem\n"
            "from mpi4py.futures import MPIPoolExecutor\n"
            f"CASE = {json.dumps(seven_wire(increments=2))!r}\n"
            "if __name__ == '__main__':\n"
            "    import json\n"
            "    with MPIPoolExecutor() as pool:\n"
            "        t = strandfem.sweep(strandfem.Case.from_dict(json.loads(CASE)), [0.05, 0.2, 0.3], sys.argv[1],\n"
            "                            key='contact.friction', executor=pool)\n"
            "    print('STATUS', ','.join(t['status']))\n")
        with tempfile.TemporaryDirectory() as folder:
            run = _run_under_mpiexec(script, 3, ["-m", "mpi4py.futures"], os.path.join(folder, "out"))
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            self.assertIn("STATUS converged,converged,converged", run.stdout)
            for value in ("0.05", "0.2", "0.3"):
                summary = strandfem.read_results(os.path.join(folder, "out", f"contact.friction={value}")).summary
                self.assertEqual(summary["status"], "converged")

    @unittest.skipUnless(os.environ.get("STRANDFEM_BUILD_DIR"), "needs the build folder")
    def test_installed_package_imports_and_runs_away_from_the_build(self):
        with tempfile.TemporaryDirectory() as folder:
            prefix = os.path.join(folder, "prefix")
            subprocess.run([os.environ["STRANDFEM_CMAKE_COMMAND"], "--install", os.environ["STRANDFEM_BUILD_DIR"], "--prefix",
                            prefix], check=True, capture_output=True)
            site = os.path.join(prefix, "lib", f"python{sys.version_info[0]}.{sys.version_info[1]}", "dist-packages")
            code = ("import strandfem, sys; assert strandfem.__file__.startswith(sys.argv[1]), strandfem.__file__; "
                    "r = strandfem.Case.from_yaml(sys.argv[2]).run('out', threads=1); print(r.status)")
            case = os.path.join(prefix, "share", "strandfem", "cases", "paper", "seven_wire_fixed.yaml")
            env = dict(_without_mpi_singleton(), PYTHONPATH=site)
            run = subprocess.run([sys.executable, "-c", code, prefix, case], cwd=folder, env=env, capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertEqual(run.stdout.strip(), "converged")

    def test_worked_example_of_docs_runs_and_lies_between_the_bounds(self):
        example = os.path.join(SOURCE, "python", "examples", "friction_sweep.py")
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "friction")
            run = subprocess.run([sys.executable, example, out], capture_output=True, text=True, timeout=240,
                                 env=_without_mpi_singleton())
            self.assertEqual(run.returncode, 0, run.stderr)
            import pandas
            table = pandas.read_csv(os.path.join(out, "sweep.csv"))
            self.assertEqual(list(table["status"]), ["converged"] * 3)
            ei = list(table["secant_ei_Nm2"])
            self.assertEqual(ei, sorted(ei))  # stiffer as friction grows (paper section 5.1)
            loops = list(table["loop_area_Nmm"])
            self.assertEqual(loops, sorted(loops, reverse=True))  # and less friction loss
            summary = strandfem.read_results(table["folder"][0]).summary
            for value in ei:
                self.assertTrue(summary["EI_min_Nm2"] < value < summary["EI_max_Nm2"], value)
            self.assertTrue(os.path.exists(os.path.join(out, "loops.png")))
            # The program's figures from Python, for one variant and for the sweep.
            drawn = [os.path.basename(p) for p in strandfem.plot.bending(strandfem.read_results(table["folder"][0]))]
            self.assertIn("bending_hysteresis.png", drawn)
            self.assertIn("bending_deflection.png", drawn)
            self.assertTrue(os.path.exists(strandfem.plot.sweep(out)))

    def test_ctrl_c_during_a_run_keeps_the_converged_increments(self):
        case = strandfem.Case.from_dict(seven_wire(increments=30))
        import signal
        import threading

        def interrupt_soon(report):
            if report["increment"] == 1:  # SIGINT 50 ms later, while the library solves the next increments
                threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT)).start()

        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "interrupted")
            self.assertLess(len(self._interrupted_run(case, out, interrupt_soon).history), 30)
            self.assertTrue(case.run(out, threads=1, resume=True).converged)

    def test_a_run_that_cannot_go_on_returns_what_it_tried(self):
        wire = {  # a straight wire twisted far past what three Newton iterations and one cut-back can carry
            "title": "over-twisted wire",
            "materials": {"steel": {"E": 200000, "nu": 0.3}},
            "beams": [{"name": "wire", "material": "steel", "section": {"diameter": 3.0},
                       "shape": {"type": "straight", "start": [0, 0, 0], "end": [0, 0, 100]}, "elements": 6}],
            "supports": [{"at": {"beam": "wire", "point": "start"}, "fix": "all"},
                         {"at": {"beam": "wire", "point": "end"}, "fix": ["ux", "uy", "rx", "ry"]}],
            "steps": [{"name": "twist", "increments": 2, "forces": [{"at": {"beam": "wire", "point": "end"},
                                                                      "moment": [0, 0, 9.0e7]}]}],
            "solver": {"max_iterations": 3, "max_cutbacks": 1, "automatic_stabilization": False},
        }
        with tempfile.TemporaryDirectory() as folder:
            results = strandfem.Case.from_dict(wire).run(os.path.join(folder, "twist"), threads=1)
            self.assertFalse(results.converged)
            self.assertEqual(results.status, "not_converged")
            self.assertIn("Newton did not converge", results.message)
            self.assertIn("tried:", results.message)

    def test_read_results_refuses_a_folder_without_summary(self):
        with tempfile.TemporaryDirectory() as folder:
            with self.assertRaises(FileNotFoundError):
                strandfem.read_results(folder)


def _run_under_mpiexec(script, ranks, python_options, out):
    """Writes `script` beside `out` and runs it with `out` as its argument on `ranks` MPI ranks."""
    path = out + "_script.py"
    with open(path, "w") as f:
        f.write(script)
    return subprocess.run([MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks), sys.executable,
                           *python_options, path, out], capture_output=True, text=True, timeout=240,
                          env=_without_mpi_singleton())


def _per_rank_outputs(prefix, ranks):
    """What each rank of a script run by _run_under_mpiexec wrote to PREFIX_<rank>."""
    outputs = []
    for rank in range(ranks):
        with open(f"{prefix}_{rank}") as f:
            outputs.append(f.read())
    return outputs


def _without_mpi_singleton():
    """This process's environment without what an earlier run's MPI (MUMPS) set for itself, which would make the
    mpiexec it starts take it for its own launcher."""
    return {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PRTE_"))}


if __name__ == "__main__":
    unittest.main()
