"""reelsim from Python: wind a reel from a scene, or read a result file, into numpy arrays.

    import reelsim
    r = reelsim.run("cases/newsprint-taper.yaml", sets={"winding.tension.end": 250})
    r.radius, r.pressure, r.sigma_theta, r.core_pressure      # numpy arrays, floats
    r2 = reelsim.read("newsprint-taper.h5")                      # the same Result from HDF5
    f = reelsim.fit_stack(strain, pressure, law="pfeiffer")      # a stack test's law, with CIs
    r.storage, r.defects, r.history                              # stages, verdicts, history
    runs = reelsim.read("compare.h5")                            # [Result, ...]; Sweep, Optimization

The package calls the shared library libreelsim (ctypes); see docs/python.md.
"""

from ._result import Result
from ._errors import Error, InputError, SolverError
from ._run import run
from ._fit import fit_stack, StackFit
from ._read import read as _read_run
from ._stored import Storage, History
from ._files import Sweep, Optimization, read_any as _read_any
from . import _lib


def read(path):
    """Reads a file reelsim wrote (docs/output.md, docs/python.md): a run file into a
    Result (with its storage stages, defect verdicts and history), a compare file into a
    list of Results in run order (each with its name, "2-lo"), a sweep file into a Sweep,
    an optimize history into an Optimization. Raises InputError when the file is not
    there or is not a reelsim file."""
    return _read_any(path, _read_run)


__version__ = _lib.rs_version().decode()

__all__ = ["run", "read", "fit_stack", "StackFit", "Result", "Storage", "History", "Sweep", "Optimization", "Error", "InputError", "SolverError", "__version__"]
