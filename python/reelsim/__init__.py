"""reelsim from Python: wind a reel from a scene, or read a result file, into numpy arrays.

    import reelsim
    r = reelsim.run("cases/newsprint-taper.yaml", sets={"winding.tension.end": 250})
    r.radius, r.pressure, r.sigma_theta, r.core_pressure      # numpy arrays, floats
    r2 = reelsim.read("newsprint-taper.h5")                      # the same Result from HDF5
    f = reelsim.fit_stack(strain, pressure, law="pfeiffer")      # a stack test's law, with CIs

The package calls the shared library libreelsim (ctypes); see docs/python.md.
"""

from ._result import Result
from ._errors import Error, InputError, SolverError
from ._run import run
from ._read import read
from ._fit import fit_stack, StackFit
from . import _lib

__version__ = _lib.rs_version().decode()

__all__ = ["run", "read", "fit_stack", "StackFit", "Result", "Error", "InputError", "SolverError", "__version__"]
