"""reelsim.read: a reelsim HDF5 run file (docs/output.md) into a Result, through the
library's own reader (rs_reader, include/reelsim/reader.h): one implementation of the
layout and of its checks (checksums, declared sizes, links, types) for the CLI and Python."""

import ctypes
import os

import numpy as np

from . import _lib
from ._errors import Error, InputError
from ._result import Result

# per-layer arrays: (Result field, dataset, required)
_LAYERS = (("radius", "/layers/radius", True),
           ("wound_on_tension", "/layers/wound_on_tension", True),
           ("web_tension", "/layers/web_tension", False),
           ("nip_load", "/layers/nip_load", False),
           ("air_film", "/layers/air_film", False),
           ("air_film_entrained", "/layers/air_film_entrained", False),
           ("sigma_r", "/final/sigma_r", True),
           ("sigma_theta", "/final/sigma_theta", True),
           ("pressure", "/final/pressure", True),
           ("at_speed_sigma_r", "/final_at_speed/sigma_r", False),
           ("at_speed_sigma_theta", "/final_at_speed/sigma_theta", False))

_KINDS = {_lib.RS_READER_FLOAT: "floating-point numbers", _lib.RS_READER_INTEGER: "integers",
          _lib.RS_READER_STRING: "strings", _lib.RS_READER_OTHER: "neither numbers nor text"}


def _fail(status):
    """The library's error record as the exception of its status."""
    msg = _lib.rs_error_message().decode("utf-8", "replace")
    if status == _lib.RS_ERR_INPUT:
        return InputError(msg, "input")
    name = _lib.rs_status_name(status).decode()
    return Error(f"{name}: {msg}", name)


class _File:
    def __init__(self, path):
        self.path = path
        self.r = ctypes.c_void_p()
        st = _lib.rs_reader_open(os.fsencode(path), ctypes.byref(self.r))
        if st != _lib.RS_OK:
            raise _fail(st)

    def close(self):
        _lib.rs_reader_close(ctypes.byref(self.r))

    def exists(self, dpath):
        return bool(_lib.rs_reader_exists(self.r, dpath.encode()))

    def floats(self, dpath, rank):
        """The floating-point dataset dpath of rank 1 (or 0: one value) as float64."""
        kind, k, dims = ctypes.c_int(), ctypes.c_int(), (ctypes.c_size_t * 2)()
        st = _lib.rs_reader_inspect(self.r, dpath.encode(), ctypes.byref(kind), ctypes.byref(k),
                                    ctypes.byref(dims))
        if st != _lib.RS_OK:
            raise _fail(st)
        if kind.value != _lib.RS_READER_FLOAT:
            raise InputError(f"{self.path}: '{dpath}' holds {_KINDS.get(kind.value, '?')} "
                             "(expected floating-point numbers)", "input")
        if k.value != rank:
            raise InputError(f"{self.path}: '{dpath}' has {k.value} dimensions "
                             f"(expected {rank})", "input")
        data, n = ctypes.POINTER(ctypes.c_double)(), ctypes.c_size_t()
        st = _lib.rs_reader_read_1d(self.r, dpath.encode(), ctypes.byref(data), ctypes.byref(n))
        if st != _lib.RS_OK:
            raise _fail(st)
        try:
            if n.value == 0:
                return np.empty(0)
            return np.ctypeslib.as_array(data, shape=(n.value,)).copy()
        finally:
            _lib.rs_reader_free_data(ctypes.byref(data))

    def attr(self, name, kind, default):
        """Root attribute `name` as kind (str, float or int), default when absent."""
        if not self._has_attr(name):
            return default
        if kind is str:
            v = ctypes.c_void_p()
            st = _lib.rs_reader_attr_string(self.r, b"/", name.encode(), ctypes.byref(v))
            if st != _lib.RS_OK:
                raise _fail(st)
            try:
                return ctypes.string_at(v.value).decode("utf-8", "replace")
            finally:
                _lib.rs_reader_free_text(ctypes.byref(v))
        if kind is float:
            v = ctypes.c_double()
            st = _lib.rs_reader_attr_double(self.r, b"/", name.encode(), ctypes.byref(v))
        else:
            v = ctypes.c_longlong()
            st = _lib.rs_reader_attr_int64(self.r, b"/", name.encode(), ctypes.byref(v))
        if st != _lib.RS_OK:
            raise _fail(st)
        return kind(v.value)

    def _has_attr(self, name):
        # the reader says "has no attribute" as an input error; anything else is a fault
        v = ctypes.c_double()
        st = _lib.rs_reader_attr_double(self.r, b"/", name.encode(), ctypes.byref(v))
        if st == _lib.RS_OK:
            return True
        msg = _lib.rs_error_message().decode("utf-8", "replace")
        return f"has no attribute '{name}'" not in msg


def read(path):
    """Reads the run file `path` (written by `reelsim run` or rs_output_write) into a
    Result: /layers/radius, /layers/wound_on_tension, /layers/web_tension,
    /layers/nip_load, /final/sigma_r, /final/sigma_theta, /final/pressure,
    /final/core_pressure and the root attributes wall_seconds, title and complete.

    Raises InputError when the file is not there, is not a reelsim file (root attribute
    program), is a comparison, lacks a dataset of a run file, is damaged (a checksum
    does not match, a declared size the file cannot hold, a link to another file), or
    holds an array of the wrong type (integers, booleans, complex numbers: never
    converted) or length (every per-layer array as long as /layers/radius and as the
    root attribute layers)."""
    p = os.fspath(path)
    f = _File(p)
    try:
        if _lib.rs_reader_is_compare(f.r):
            raise InputError(f"{p}: a comparison file (it has /runs), not a run file",
                             "input")
        need = [d for _, d, required in _LAYERS if required] + ["/final/core_pressure"]
        for dpath in need:
            if not f.exists(dpath):
                raise InputError(f"{p}: not a reelsim run file (no {dpath})", "input")
        a = {k: f.floats(d, 1) if f.exists(d) else np.empty(0) for k, d, _ in _LAYERS}
        n = a["radius"].shape[0]
        for k, d, _ in _LAYERS:
            if f.exists(d) and a[k].shape[0] != n:
                raise InputError(f"{p}: '{d}' holds {a[k].shape[0]} values but "
                                 f"/layers/radius {n}", "input")
        layers = f.attr("layers", int, n)
        if layers != n:
            raise InputError(f"{p}: the root attribute layers is {layers} but /layers/radius "
                             f"holds {n} values", "input")

        def scalar(d):
            return float(f.floats(d, 0)[0]) if f.exists(d) else float("nan")

        return Result(radius=a["radius"], sigma_r=a["sigma_r"], sigma_theta=a["sigma_theta"],
                      pressure=a["pressure"], wound_on_tension=a["wound_on_tension"],
                      core_pressure=scalar("/final/core_pressure"),
                      wall_seconds=f.attr("wall_seconds", float, float("nan")),
                      web_tension=a["web_tension"], nip_load=a["nip_load"],
                      title=f.attr("title", str, ""),
                      air_film=a["air_film"], air_film_entrained=a["air_film_entrained"],
                      at_speed_sigma_r=a["at_speed_sigma_r"],
                      at_speed_sigma_theta=a["at_speed_sigma_theta"],
                      at_speed_core_pressure=scalar("/final_at_speed/core_pressure"),
                      complete=bool(f.attr("complete", int, 1)))
    finally:
        f.close()
