"""Figures of results folders as PNG files: the same code as the program's `--plots` and `strandfem sweep`
(scripts/plot_bending.py and scripts/plot_sweep.py, shipped inside the package)."""
import os


def bending(results):
    """A bent strand's figures in its results folder (Results or a folder): bending_hysteresis.png,
    bending_deflection.png, and where the run wrote its profiles bending_wire_forces.png,
    bending_contact_forces.png, bending_status_maps.png. Returns the paths written."""
    from strandfem import _plot_bending
    return _plot_bending.plot_folder(os.fspath(getattr(results, "folder", results)))


def sweep(out_dir):
    """The variants of a sweep folder (strandfem.sweep or `strandfem sweep`) on one figure, out_dir/sweep.png.
    Returns its path, or None where no variant has results to draw."""
    from strandfem import _plot_sweep
    _plot_sweep.main(os.fspath(out_dir))
    path = os.path.join(os.fspath(out_dir), "sweep.png")
    return path if os.path.exists(path) else None
