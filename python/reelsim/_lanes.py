"""Result.lanes: the lanes across the width (docs/lanes.md) as numpy arrays, from a run in
this process (the rs_lanes_result_<field> accessors, reel.h) or from a run file's /lanes
(the library's reader).

A dict: per lane "x", "width", "caliper" (m), "core_pressure" (Pa), "outer_radius" (m);
per layer "strain"; layers x lanes (row k = layer k) "wound_on_tension", "web_tension",
"slack" (bool, web tension 0), "nip_load" (with a nip), "final_sigma_r",
"final_sigma_theta" (Pa), "final_radius" (m). None for a reel without lanes."""

import ctypes as _c

import numpy as np

from . import _lib

# (Result.lanes key, which is also the C accessor's rs_lanes_result_<key>, and the file's
# /lanes dataset)
_NAMES = (("x", "x"), ("width", "width"), ("caliper", "caliper"),
          ("core_pressure", "core_pressure"), ("outer_radius", "outer_radius"),
          ("strain", "strain"), ("wound_on_tension", "wound_on_tension"),
          ("web_tension", "web_tension"), ("nip_load", "nip_load"),
          ("final_sigma_r", "final/sigma_r"), ("final_sigma_theta", "final/sigma_theta"),
          ("final_radius", "final/radius"))

# const double *rs_lanes_result_<key>(res, &rows, &cols)
_array = {key: _lib._fn("rs_lanes_result_" + key, _c.POINTER(_c.c_double), _c.c_void_p,
                        _c.POINTER(_c.c_int), _c.POINTER(_c.c_int)) for key, _ in _NAMES}


def _finish(d):
    if "web_tension" in d:
        d["slack"] = d["web_tension"] == 0.0
    return d


def of_result(res):
    """The lanes of a C result (a ctypes pointer), None without lanes."""
    d = {}
    for key, _ in _NAMES:
        rows, cols = _c.c_int(0), _c.c_int(0)
        p = _array[key](res, _c.byref(rows), _c.byref(cols))
        if not p:
            continue
        n = rows.value * (cols.value or 1)
        a = np.ctypeslib.as_array(p, shape=(n,)).copy() if n else np.empty(0)
        d[key] = a.reshape(rows.value, cols.value) if cols.value else a
    return _finish(d) if d else None


def of_file(reader, base=""):
    """The lanes of a run file through a _files._Reader (base: the run's group), None
    without /lanes."""
    if not reader.has(base + "/lanes/x"):
        return None
    d = {}
    for key, name in _NAMES:
        path = f"{base}/lanes/{name}"
        if not reader.has(path):
            continue
        two = name not in ("x", "width", "caliper", "core_pressure", "outer_radius", "strain")
        d[key] = reader.matrix(path) if two else reader.array(path)
    return _finish(d)
