"""Sweeps: one case in variants, each solved by the library in a process of its own, on this machine's cores or on
MPI ranks across machines (an mpi4py.futures.MPIPoolExecutor)."""
import concurrent.futures
import csv
import json
import multiprocessing
import os

from strandfem import _core
from strandfem.case import _yaml_scalar


def _solve(text, name, folder, threads):
    from strandfem.case import Case  # in the worker process
    Case.from_text(text, name).run(folder, threads=threads)
    return folder


def _summary(folder, error):
    try:
        with open(os.path.join(folder, "summary.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {"status": "failed", "message": str(error)}


def _row(values, folder, error, header):
    fields = next(csv.reader([_core.sweep_result_fields(json.dumps(_summary(folder, error)))]))
    row = dict(values)
    row["variant"] = row["results"] = os.path.basename(folder)  # as `strandfem sweep` names them (plot_sweep.py)
    row["folder"] = folder
    for column, field in zip(header, fields):
        row[column] = field if column == "status" else (float(field) if field else float("nan"))
    return row


def _run_here(job, threads):
    _, variant, folder = job
    try:
        variant.run(folder, threads=threads)
        return None
    except Exception as e:  # noqa: BLE001 - a variant that fails does not stop the others
        return e


def product(values):
    """Every combination of several keys' values, as variants for sweep(): product({"contact.friction": [0.3, 0.5],
    "strand.length": [300, 500]}) gives four dicts, the last key varying fastest."""
    import itertools
    keys = list(values)
    return [dict(zip(keys, combination)) for combination in itertools.product(*(values[k] for k in keys))]


def _case_jobs(cases, out_dir):
    """One job per case of a list, named after its file (or name) as `strandfem sweep CASE...` names them."""
    jobs, names = [], set()
    for case in cases:
        name = os.path.splitext(os.path.basename(case._name.split(" [")[0]))[0] or "case"  # "[...]": a variant's keys
        if name in names:
            name += f"_{len(jobs) + 1}"
        names.add(name)
        jobs.append(({"case": case._name}, case, os.path.join(os.fspath(out_dir), name)))
    return jobs


def sweep(case, variants, out_dir, key=None, processes=None, threads=1, executor=None, mpi=False, plots=False):
    """Runs the variants of `case` into out_dir/<variant> and returns one row per variant as a DataFrame (also
    written to out_dir/sweep.csv): the variant's keys, its name and folder, and the columns of `strandfem sweep`'s
    sweep.csv (status; axial strain, force, secant stiffness and its ratio to the theory; for bending the cycles and
    the last cycle's peak load, peak deflection, loop area, secant EI and return loop area).

    case: a Case, or a list of Cases run as they are (variants then None; each row's `case` names it).
    variants: values of `key` ("contact.friction"), or dicts {key: value, ...} without it (product() makes them for
    several keys at once).
    processes: variants solved at once on this machine (default: its cores / threads), each with `threads`.
    mpi: the script runs under `mpiexec -n N`; the N ranks (on one machine or several) take the variants from a
    shared queue, each the next one not yet taken when it is free, solving it with `threads`; every rank returns the
    whole table (rank 0 writes sweep.csv). Each rank's OpenBLAS runs `threads` threads too.
    executor: a concurrent.futures executor to use instead, e.g. mpi4py.futures.MPIPoolExecutor().
    plots: also draw out_dir/sweep.png (strandfem.plot.sweep), as `strandfem sweep` does.
    Every variant is read and checked before any runs; a variant that stops or fails has its status in its row.
    """
    import pandas

    if isinstance(case, (list, tuple)):
        if variants is not None or key is not None:
            raise ValueError("sweep: a list of cases runs the cases as they are; give variants of one case instead")
        jobs = _case_jobs(case, out_dir)
    else:
        variants = [{key: v} for v in variants] if key is not None else [dict(v) for v in variants]
        jobs = []
        for values in variants:
            variant = case.with_values(values)
            name = ",".join(_core.variant_folder_name(k, _yaml_scalar(v)) for k, v in values.items())
            jobs.append((values, variant, os.path.join(os.fspath(out_dir), name)))
    os.makedirs(out_dir, exist_ok=True)
    header = _core.sweep_result_header().split(",")
    write = True
    if mpi:
        from mpi4py import MPI
        comm = MPI.COMM_WORLD
        rank = comm.Get_rank()
        _limit_blas_threads(threads)
        mine = {}
        for i in _shared_queue(comm, len(jobs)):
            mine[i] = _row(jobs[i][0], jobs[i][2], _run_here(jobs[i], threads), header)
        everything = {}
        for part in comm.allgather(mine):
            everything.update(part)
        rows = [everything[i] for i in range(len(jobs))]
        write = rank == 0
    elif executor is None:
        workers = processes or max(1, (os.cpu_count() or 1) // max(1, threads))
        # Fresh interpreters: a forked child would inherit this process's OpenMP and MPI state.
        with concurrent.futures.ProcessPoolExecutor(max_workers=max(1, min(workers, len(jobs))),
                                                    mp_context=multiprocessing.get_context("spawn")) as pool:
            rows = _collect(pool, jobs, threads, header)
    else:
        rows = _collect(executor, jobs, threads, header)
    table = pandas.DataFrame(rows)
    if write:
        table.to_csv(os.path.join(out_dir, "sweep.csv"), index=False)
        if plots:
            from strandfem import plot
            plot.sweep(out_dir)
    return table


def _limit_blas_threads(threads):
    """OpenBLAS (MUMPS's BLAS) would otherwise take every core in each rank: ranks sharing a machine oversubscribe it."""
    import ctypes
    try:
        ctypes.CDLL("libopenblas.so.0").openblas_set_num_threads(threads)
    except (OSError, AttributeError):
        pass  # another BLAS: its own threads setting applies


def _shared_queue(comm, count):
    """Variant indices for this rank: each rank takes the next one not yet taken whenever it is free (a counter on
    rank 0 that every rank fetches and increments), so that a long variant does not hold up the ones behind it."""
    import numpy
    from mpi4py import MPI

    item = MPI.INT64_T.Get_size()
    window = MPI.Win.Allocate(item if comm.Get_rank() == 0 else 0, item, comm=comm)
    if comm.Get_rank() == 0:
        window.Lock(0)
        window.Put(numpy.zeros(1, dtype=numpy.int64), 0)
        window.Unlock(0)
    comm.Barrier()
    one, taken = numpy.ones(1, dtype=numpy.int64), numpy.zeros(1, dtype=numpy.int64)
    while True:
        window.Lock(0)
        window.Fetch_and_op(one, taken, 0, 0, MPI.SUM)
        window.Unlock(0)
        if taken[0] >= count:
            break
        yield int(taken[0])
    comm.Barrier()  # no rank frees the counter while another may still fetch from it
    window.Free()


def _collect(executor, jobs, threads, header):
    futures = [executor.submit(_solve, variant.to_yaml(), variant._name, folder, threads) for _, variant, folder in jobs]
    rows = []
    for (values, _, folder), future in zip(jobs, futures):
        try:
            future.result()
            error = None
        except Exception as e:  # noqa: BLE001 - the variant's own summary.json says what happened where it exists
            error = e
        rows.append(_row(values, folder, error, header))
    return rows
