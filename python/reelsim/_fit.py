"""reelsim.fit_stack: the radial stack law fitted to a stack test, by the library's own fit
(rs_fit_stack, src/fit/stack_fit.c; docs/calibrate.md)."""

import ctypes

import numpy as np

from . import _lib
from ._run import _raise, _last_message


class StackFit:
    """The fitted law: `law`, `names`, `values` and `half_widths` (the 95 % confidence
    intervals are values +- half_widths), `intervals` as (low, high) pairs, `params` as a
    dict name -> value, `rms` (RMS strain residual), `worst` (index of the worst point) and
    `worst_residual` (model - measured strain there)."""

    def __init__(self, law, names, values, half_widths, rms, worst, worst_residual):
        self.law = law
        self.names = names
        self.values = values
        self.half_widths = half_widths
        self.rms = rms
        self.worst = worst
        self.worst_residual = worst_residual

    @property
    def params(self):
        return dict(zip(self.names, self.values))

    @property
    def intervals(self):
        return [(v - h, v + h) for v, h in zip(self.values, self.half_widths)]

    def __repr__(self):
        body = ", ".join(f"{n}={v:.6g}+-{h:.2g}" for n, v, h in
                         zip(self.names, self.values, self.half_widths))
        return f"StackFit({self.law}: {body}; rms={self.rms:.3g})"


def fit_stack(strain, pressure, law="pfeiffer", terms=0):
    """Fits `law` ("pfeiffer", "hakiel", "linear" or "table") to a stack test: `strain`
    (compression positive) at `pressure` (Pa), sequences of equal length. `terms`: the
    Hakiel coefficients or the table's points (0: the default, 3 and 6). Raises InputError
    when the data cannot determine the law (the reason in the message)."""
    e = np.ascontiguousarray(strain, dtype=float)
    p = np.ascontiguousarray(pressure, dtype=float)
    if e.shape != p.shape or e.ndim != 1:
        raise ValueError("strain and pressure must be 1-D sequences of the same length")
    dp = ctypes.POINTER(ctypes.c_double)
    m = _lib.RS_FIT_MAX_PARAMS
    n_par = ctypes.c_int(0)
    names = ctypes.create_string_buffer(16 * m)
    values, half, stats = (ctypes.c_double * m)(), (ctypes.c_double * m)(), (ctypes.c_double * 4)()
    _lib.rs_error_clear()
    st = _lib.rs_fit_stack_flat(len(e), p.ctypes.data_as(dp), e.ctypes.data_as(dp),
                                str(law).encode(), int(terms), ctypes.byref(n_par), names,
                                values, half, stats)
    if st != _lib.RS_OK:
        _raise(st, _last_message())
    k = n_par.value
    nm = [names.raw[16 * i:16 * (i + 1)].split(b"\0", 1)[0].decode() for i in range(k)]
    return StackFit(str(law), nm, np.array(values[:k]), np.array(half[:k]), stats[0],
                    int(stats[1]), stats[2])
