"""A results folder (docs/results.md) as pandas tables and the summary as a dict."""
import json
import os


class Results:
    """The files of a results folder written by `strandfem run` or Case.run, read on first use."""

    _TABLES = {
        "history": "history.csv",
        "loops": "loops.csv",
        "deflection_curves": "deflection_curves.csv",
        "contacts": "contacts.csv",
        "wires": "wires.csv",
        "wire_profiles": "wire_profiles.csv",
        "contact_profiles": "contact_profiles.csv",
        "displacements": "displacements.csv",
    }

    def __init__(self, folder, outcome=None):
        self.folder = os.fspath(folder)
        self._outcome = outcome or {}
        self._cache = {}

    @property
    def summary(self):
        """summary.json as a dict (status, model sizes, closed-form references, what the run measured)."""
        with open(os.path.join(self.folder, "summary.json")) as f:
            return json.load(f)

    @property
    def status(self):
        """converged, not_converged, stopped, output_error, failed (running while a run writes the folder)."""
        return self.summary.get("status")

    @property
    def converged(self):
        """The run reached the end of its load protocol."""
        return self.status == "converged"

    @property
    def message(self):
        """Why a run stopped or failed, and what to try."""
        return self.summary.get("message", "")

    @property
    def wall_seconds(self):
        """The wall time of the run (of this invocation, for a run from Case.run)."""
        return self._outcome.get("wall_seconds", self.summary.get("wall_time_s"))

    def table(self, name):
        """One CSV file of the folder as a DataFrame (name: a key of Results.tables() or a file name); None where
        the run wrote no such file (a table of bending results for an axial case)."""
        file = self._TABLES.get(name, name)
        if file not in self._cache:
            path = os.path.join(self.folder, file)
            if not os.path.exists(path):
                return None
            import pandas
            self._cache[file] = pandas.read_csv(path)
        return self._cache[file]

    def arrays(self, name, *columns):
        """Columns of a table as numpy arrays: `strain, force = results.arrays("history", "axial_strain",
        "axial_force_N")`; one column gives one array, none gives a dict of every column. KeyError names a column
        the table lacks; None where the run wrote no such file."""
        frame = self.table(name)
        if frame is None:
            return None
        missing = [c for c in columns if c not in frame.columns]
        if missing:
            raise KeyError(f"{name} has no column {', '.join(missing)} (it has {', '.join(frame.columns)})")
        if not columns:
            return {c: frame[c].to_numpy() for c in frame.columns}
        arrays = tuple(frame[c].to_numpy() for c in columns)
        return arrays[0] if len(arrays) == 1 else arrays

    @classmethod
    def tables(cls):
        """The tables by name (also attributes: results.history) and their files."""
        return dict(cls._TABLES)

    def __getattr__(self, name):
        if name in Results._TABLES:
            return self.table(name)
        raise AttributeError(name)

    def __repr__(self):
        return f"Results({self.folder!r}, status={self.status!r})"


def read_results(folder):
    """A results folder written by the program or by Case.run."""
    if not os.path.exists(os.path.join(folder, "summary.json")):
        raise FileNotFoundError(f"{folder}: no summary.json (not a StrandFEM results folder)")
    return Results(folder)
