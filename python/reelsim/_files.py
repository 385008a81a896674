"""reelsim.read for every file reelsim writes (docs/output.md): a run file into a Result
with its storage stages, defect verdicts and history; a compare file into a list of
Results, one per run; a sweep file into a Sweep; an optimize history into an Optimization.
Read through the library's HDF5 reader (reelsim/reader.h) with ctypes."""

import ctypes
import os
from dataclasses import dataclass, field, replace

import numpy as np

from . import _lanes, _lib
from ._errors import Error, InputError
from ._result import Result
from ._stored import History, Storage, defects_from_file

_c = ctypes
_VP = _c.c_void_p
_CP = _c.c_char_p
_SZ = _c.c_size_t
_DPP = _c.POINTER(_c.POINTER(_c.c_double))

_open = _lib._fn("rs_reader_open", _c.c_int, _CP, _c.POINTER(_VP))
_close = _lib._fn("rs_reader_close", None, _c.POINTER(_VP))
_is_compare = _lib._fn("rs_reader_is_compare", _c.c_int, _VP)
_runs = _lib._fn("rs_reader_runs", _c.c_int, _VP)
_run_base = _lib._fn("rs_reader_run_base", _CP, _VP, _c.c_int)
_run_name = _lib._fn("rs_reader_run_name", _CP, _VP, _c.c_int)
_exists = _lib._fn("rs_reader_exists", _c.c_int, _VP, _CP)
_read_1d = _lib._fn("rs_reader_read_1d", _c.c_int, _VP, _CP, _DPP, _c.POINTER(_SZ))
_read_2d = _lib._fn("rs_reader_read_2d", _c.c_int, _VP, _CP, _DPP, _c.POINTER(_SZ),
                    _c.POINTER(_SZ))
_read_strings = _lib._fn("rs_reader_read_strings", _c.c_int, _VP, _CP,
                         _c.POINTER(_c.POINTER(_CP)), _c.POINTER(_SZ))
_free_strings = _lib._fn("rs_reader_free_strings", None, _c.POINTER(_c.POINTER(_CP)), _SZ)
_attr_string = _lib.rs_reader_attr_string  # declared once (_lib.py): ctypes shares it
_attr_double = _lib._fn("rs_reader_attr_double", _c.c_int, _VP, _CP, _CP,
                        _c.POINTER(_c.c_double))
_libc_free = _c.CDLL(None).free  # the reader's arrays come from the process's malloc
_libc_free.argtypes = [_VP]
_libc_free.restype = None


@dataclass(eq=False)
class Sweep:
    """A sweep file (`reelsim sweep`): R runs of one scene at K keys' values.

    parameters  the K keys varied
    values      R x K: each run's values (a word-valued key: the index of its word)
    words       {key: [words]} for the word-valued keys
    figures     {name: R values}: core_pressure, ..., status, with storage stages
                storage_core_pressure, ..., with lanes ridge_height, max_lane_pressure,
                slack_lanes (NaN where a run failed)
    profiles    per run (with --profiles) {"radius", "sigma_r", "sigma_theta"}, else []
    scene_file  the scene swept
    """

    parameters: list
    values: np.ndarray
    figures: dict
    words: dict = field(default_factory=dict)
    profiles: list = field(default_factory=list)
    scene_file: str = ""


@dataclass(eq=False)
class Optimization:
    """An optimize history file (`reelsim optimize`): every evaluation in order.

    parameters, lower, upper  the varied keys and their ranges
    values       E x K: the values of each evaluation
    phase        E: 0 the Latin-hypercube start, 1 COBYLA
    figures      {name: E values} (status 0: the run finished)
    best         index of the best feasible evaluation, -1 if none
    objective, sense, constraints  as given ("storage_core_pressure <= 2000000", ...)
    """

    parameters: list
    lower: np.ndarray
    upper: np.ndarray
    values: np.ndarray
    phase: np.ndarray
    figures: dict
    best: int
    objective: str = ""
    sense: str = ""
    constraints: list = field(default_factory=list)


class _Reader:
    def __init__(self, path):
        self.path = os.fspath(path)
        self.r = _VP()
        st = _open(os.fsencode(self.path), _c.byref(self.r))
        if st != _lib.RS_OK:
            msg = _lib.rs_error_message().decode("utf-8", "replace")
            _close(_c.byref(self.r))
            raise InputError(msg, "input") if st == _lib.RS_ERR_INPUT else Error(msg)

    def close(self):
        _close(_c.byref(self.r))

    def _fail(self, st):
        msg = _lib.rs_error_message().decode("utf-8", "replace")
        raise InputError(msg, "input") if st == _lib.RS_ERR_INPUT else Error(msg)

    def has(self, path):
        return bool(_exists(self.r, path.encode()))

    def array(self, path, default=None):
        if not self.has(path):
            return np.empty(0) if default is None else default
        p, n = _c.POINTER(_c.c_double)(), _SZ(0)
        st = _read_1d(self.r, path.encode(), _c.byref(p), _c.byref(n))
        if st != _lib.RS_OK:
            self._fail(st)
        try:
            return np.ctypeslib.as_array(p, shape=(n.value,)).copy() if n.value else np.empty(0)
        finally:
            _libc_free(_c.cast(p, _VP))

    def matrix(self, path):
        if not self.has(path):
            return np.empty((0, 0))
        p, rows, cols = _c.POINTER(_c.c_double)(), _SZ(0), _SZ(0)
        st = _read_2d(self.r, path.encode(), _c.byref(p), _c.byref(rows), _c.byref(cols))
        if st != _lib.RS_OK:
            self._fail(st)
        try:
            n = rows.value * cols.value
            a = np.ctypeslib.as_array(p, shape=(n,)).copy() if n else np.empty(0)
            return a.reshape(rows.value, cols.value)
        finally:
            _libc_free(_c.cast(p, _VP))

    def scalar(self, path, default=float("nan")):
        a = self.array(path)
        return float(a[0]) if a.size else default

    def strings(self, path):
        if not self.has(path):
            return []
        p, n = _c.POINTER(_CP)(), _SZ(0)
        st = _read_strings(self.r, path.encode(), _c.byref(p), _c.byref(n))
        if st != _lib.RS_OK:
            self._fail(st)
        try:
            return [p[i].decode("utf-8", "replace") for i in range(n.value)]
        finally:
            _free_strings(_c.byref(p), n)

    def attr(self, path, name, default=""):
        v = _VP()
        if _attr_string(self.r, path.encode(), name.encode(), _c.byref(v)) != _lib.RS_OK:
            _lib.rs_error_clear()
            return default
        try:
            return _c.string_at(v.value).decode("utf-8", "replace")
        finally:
            _lib.rs_reader_free_text(_c.byref(v))

    def attr_number(self, path, name):
        v = _c.c_double(float("nan"))
        if _attr_double(self.r, path.encode(), name.encode(), _c.byref(v)) != _lib.RS_OK:
            _lib.rs_error_clear()
        return float(v.value)


def _extras(rd, base):
    """storage, history and defects of the run under `base` ("" or "/runs/<name>")."""
    out = {"storage": None, "history": None, "defects": {}}
    if rd.has(base + "/storage/hours"):
        g = base + "/storage"
        out["storage"] = Storage(hours=rd.array(g + "/hours"),
                                 temperature=rd.array(g + "/temperature"),
                                 humidity=rd.array(g + "/humidity"),
                                 core_pressure=rd.array(g + "/core_pressure"),
                                 sigma_r=rd.matrix(g + "/sigma_r"),
                                 sigma_theta=rd.matrix(g + "/sigma_theta"))
    if rd.has(base + "/history/layers"):
        g = base + "/history"
        out["history"] = History(layers=rd.array(g + "/layers").astype(np.int64),
                                 outer_radius=rd.array(g + "/outer_radius"),
                                 sigma_r=rd.matrix(g + "/sigma_r"),
                                 sigma_theta=rd.matrix(g + "/sigma_theta"))
    out["defects"] = defects_from_file(rd.has, rd.attr_number, rd.attr, base)
    out["lanes"] = _lanes.of_file(rd, base)
    return out


def _run_at(rd, base, name):
    """The run under `base` of a compare file, as read() gives a run file."""
    sr = rd.array(base + "/final/sigma_r")
    return Result(radius=rd.array(base + "/layers/radius"), sigma_r=sr,
                  sigma_theta=rd.array(base + "/final/sigma_theta"),
                  pressure=rd.array(base + "/final/pressure"),
                  wound_on_tension=rd.array(base + "/layers/wound_on_tension"),
                  core_pressure=rd.scalar(base + "/final/core_pressure"),
                  wall_seconds=rd.attr_number(base, "wall_seconds"),
                  web_tension=rd.array(base + "/layers/web_tension"),
                  nip_load=rd.array(base + "/layers/nip_load"),
                  title=rd.attr(base, "title"),
                  air_film=rd.array(base + "/layers/air_film"),
                  air_film_entrained=rd.array(base + "/layers/air_film_entrained"),
                  at_speed_sigma_r=rd.array(base + "/final_at_speed/sigma_r"),
                  at_speed_sigma_theta=rd.array(base + "/final_at_speed/sigma_theta"),
                  at_speed_core_pressure=rd.scalar(base + "/final_at_speed/core_pressure"),
                  name=name, **_extras(rd, base))


def _figures(rd, group, names=None):
    out = {}
    for name in names if names is not None else _children(rd, group):
        out[name] = rd.array(f"{group}/{name}")
    return out


_children_fn = _lib._fn("rs_reader_children", _c.c_int, _VP, _CP, _c.POINTER(_c.POINTER(_CP)),
                        _c.POINTER(_SZ))


def _children(rd, group):
    p, n = _c.POINTER(_CP)(), _SZ(0)
    if _children_fn(rd.r, group.encode(), _c.byref(p), _c.byref(n)) != _lib.RS_OK:
        _lib.rs_error_clear()
        return []
    try:
        return [p[i].decode() for i in range(n.value)]
    finally:
        _free_strings(_c.byref(p), n)


def _sweep(rd):
    keys = rd.strings("/sweep/parameters")
    words = {}
    for k in keys:
        w = rd.attr("/sweep/values", "words:" + k, None)
        if w:
            words[k] = w.split(",")
    profiles = []
    for i in _children(rd, "/sweep/profiles"):
        g = "/sweep/profiles/" + i
        profiles.append({k: rd.array(f"{g}/{k}") for k in ("radius", "sigma_r", "sigma_theta")})
    return Sweep(parameters=keys, values=rd.matrix("/sweep/values"),
                 figures=_figures(rd, "/sweep/figures"), words=words, profiles=profiles,
                 scene_file=rd.attr("/", "scene_file"))


def _optimization(rd):
    cons = rd.attr("/optimize", "constraints")
    return Optimization(parameters=rd.strings("/optimize/parameters"),
                        lower=rd.array("/optimize/lower"), upper=rd.array("/optimize/upper"),
                        values=rd.matrix("/optimize/values"),
                        phase=rd.array("/optimize/phase").astype(np.int64),
                        figures=_figures(rd, "/optimize/figures"),
                        best=int(rd.scalar("/optimize/best", -1)),
                        objective=rd.attr("/optimize", "objective"),
                        sense=rd.attr("/optimize", "sense"),
                        constraints=[c for c in cons.split("\n") if c])


def read_any(path, read_run):
    """The file at `path` by what it holds; `read_run` reads a run file's profile (and
    says why a file that the library's reader refuses is not a run file)."""
    try:
        rd = _Reader(path)
    except InputError:
        return read_run(path)
    try:
        if rd.has("/sweep"):
            return _sweep(rd)
        if rd.has("/optimize"):
            return _optimization(rd)
        if _is_compare(rd.r):
            return [_run_at(rd, _run_base(rd.r, i).decode(), _run_name(rd.r, i).decode())
                    for i in range(_runs(rd.r))]
        extras = _extras(rd, "")
    finally:
        rd.close()
    return replace(read_run(path), **extras)
