"""StrandFEM from Python: strand cases read and checked as the program reads them, run through the library, results
as pandas tables, sweeps over processes or MPI ranks, and the closed-form references (docs/python.md)."""
from strandfem._core import CaseError, __version__, build_info
from strandfem import plot, references
from strandfem.build import Layer, Material, Step, Strand
from strandfem.case import Case
from strandfem.results import Results, read_results
from strandfem.sweep import product, sweep

__all__ = ["Case", "CaseError", "Layer", "Material", "Results", "Step", "Strand", "build_info", "plot", "product",
           "read_results", "references", "sweep", "__version__"]
