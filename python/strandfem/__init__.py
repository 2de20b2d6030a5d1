"""StrandFEM from Python: strand cases read and checked as the program reads them, run through the library, results
as pandas tables, sweeps over processes or MPI ranks, and the closed-form references (docs/python.md)."""
import os

from strandfem._core import CaseError, __version__, build_info
from strandfem._core import conductor_table as _conductor_table
from strandfem import plot, references
from strandfem.build import Layer, Material, Step, Strand
from strandfem.case import Case
from strandfem.results import Results, read_results
from strandfem.sweep import product, sweep


def conductors(catalogue=None):
    """The conductor catalogue as a pandas DataFrame, one conductor per row (a user's CSV `catalogue` first), as
    `strandfem conductors` prints it: type, wires, outer diameter, metallic area, mass per length, EImax, EImin."""
    import pandas as pd

    header, *rows = _conductor_table("" if catalogue is None else os.fspath(catalogue))
    table = pd.DataFrame(rows, columns=header)
    for column in header[2:]:
        table[column] = pd.to_numeric(table[column])
    return table

__all__ = ["Case", "CaseError", "Layer", "Material", "Results", "Step", "Strand", "build_info", "conductors", "plot", "product",
           "read_results", "references", "sweep", "__version__"]
