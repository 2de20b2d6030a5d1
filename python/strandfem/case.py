"""A strand case: from a case file or from Python data, checked by the library's reader, run into a folder."""
import os

from strandfem import _core, build
from strandfem.results import Results


class Case:
    """A case read and checked as `strandfem run` reads it; bad input raises CaseError naming the key and its
    place (file:line:column; for a case built from data, the line and column of `to_yaml()`)."""

    def __init__(self, handle, text, name):
        self._handle = handle
        self._text = text
        self._name = name

    @classmethod
    def from_yaml(cls, path):
        """Reads a case file."""
        path = os.fspath(path)
        handle = _core.load_case(path)
        with open(path, encoding="utf-8") as f:
            return cls(handle, f.read(), path)

    @classmethod
    def from_dict(cls, data, name="<dict>"):
        """A case from nested dicts and lists with the case file's keys (docs/case-files.md); `name` stands for
        the file in messages."""
        return cls.from_text(_yaml_text(data), name)

    @classmethod
    def build(cls, strand, steps, title=None, name="<built>", **sections):
        """A case from objects: a strandfem.Strand (its layers name their strandfem.Material), a list of
        strandfem.Step, and further sections (mesh, contact, solver, output, supports) as dicts with the case file's
        keys. The materials section is collected from the layers."""
        return cls.from_dict(build.case_data(strand, steps, title, **sections), name)

    @classmethod
    def from_text(cls, text, name="<text>"):
        """A case from case-file text."""
        return cls(_core.load_case_text(text, name), text, name)

    def to_yaml(self):
        """The case-file text."""
        return self._text

    def with_values(self, values):
        """A variant: {"contact.friction": 0.7, "strand.layers.1.lay_angle": 12} sets each dot-separated key (map
        keys or 0-based list indices) as `strandfem sweep --set` does; the value is read as YAML."""
        text = self._text
        for key, value in values.items():
            text = _core.set_case_key(text, key, _yaml_scalar(value))
        label = ",".join(f"{k}={_yaml_scalar(v)}" for k, v in values.items())
        return Case.from_text(text, f"{self._name} [{label}]")

    @property
    def title(self):
        """The case's title."""
        return self._handle.title

    @property
    def warnings(self):
        """What the reader noticed but accepted (e.g. neighbouring wires overlapping at the nominal radius)."""
        return list(self._handle.warnings)

    def info(self):
        """Model sizes and the closed-form references, as `strandfem info` prints them."""
        return self._handle.info()

    def references(self):
        """The strand's closed-form references: EImax and EImin (Papailiou's bounds, N m^2) and the linear axial
        stiffness for fixed and free ends (N). Eqs. 3.1 and 3.2 are in strandfem.references."""
        info = self.info()
        stiffness = info.get("axial_stiffness_N", {})
        return {"ei_max_Nm2": info.get("EI_max_Nm2"), "ei_min_Nm2": info.get("EI_min_Nm2"),
                "axial_stiffness_fixed_N": stiffness.get("fixed_ends"), "axial_stiffness_free_N": stiffness.get("free_ends")}

    def resolved(self):
        """Every setting the run uses, defaults filled in (summary.json's `configuration`)."""
        return self._handle.resolved()

    def run(self, out_dir, threads=None, progress=None, resume=False):
        """Solves the case into `out_dir` and returns its Results.

        threads: threads for the elements and the factorizations (default: the case's solver.threads, else all).
        progress: called after each converged increment with a dict (step, step_name, increment, step_fraction,
        relative_size, cutbacks, iterations, residual).
        resume: continue from the folder's checkpoint.
        Ctrl-C, or an exception raised by `progress`, stops the run after the current Newton iteration with every
        converged increment written (summary status `stopped`; resume=True continues), then raises it.
        A run that cannot go on returns Results whose `converged` is False and whose `message` says what to try.
        """
        outcome = _core.run(self._handle, os.fspath(out_dir), threads or 0, resume, progress)
        return Results(out_dir, outcome)

    def __repr__(self):
        return f"Case({self._name!r}, title={self.title!r})"


def _yaml_scalar(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_yaml_scalar(v) for v in value) + "]"
    return repr(value) if isinstance(value, float) else str(value)


def _yaml_text(data):
    try:
        import yaml
    except ImportError:  # JSON is YAML too; messages then point into one line
        import json
        return json.dumps(data)
    return yaml.safe_dump(data, sort_keys=False, default_flow_style=None)
