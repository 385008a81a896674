"""What a wound reel carries beyond its final profile: the storage stages (docs/storage.md),
the defect verdicts (docs/defects.md) and the stress history (output.history_every), from a
live result through the library's accessors (no C struct is mirrored)."""

import ctypes
from dataclasses import dataclass, field

import numpy as np

from . import _lib

_c = ctypes
_VP = _c.c_void_p
_DP = _c.POINTER(_c.c_double)

_storage_requested = _lib._fn("rs_storage_requested", _c.c_int, _VP)
_storage_run = _lib._fn("rs_storage_run", _c.c_int, _VP, _VP, _c.POINTER(_VP))
_storage_destroy = _lib._fn("rs_storage_result_destroy", None, _c.POINTER(_VP))
_storage_stages = _lib._fn("rs_storage_result_stages", _c.c_int, _VP)
# const double *rs_storage_result_<field>(sr, &n), one accessor per array (storage.h)
_storage_array = {k: _lib._fn("rs_storage_result_" + k, _DP, _VP, _c.POINTER(_c.c_int))
                  for k in ("hours", "temperature", "humidity", "core_pressure", "sigma_r",
                            "sigma_theta")}
_storage_defects = _lib._fn("rs_storage_result_defects", _VP, _VP, _c.c_int)
_defect_destroy = _lib._fn("rs_defect_report_destroy", None, _c.POINTER(_VP))
_scene_problem = _lib._fn("rs_scene_problem", _VP, _VP)
_stage_array = {k: _lib.result_array("stage_" + k) for k in ("radius", "sigma_r", "sigma_theta")}

# Result.defects: rule -> (its run file's /defects/<group>, number figures, text figures);
# the figures named as rs_defect_report_value/_text ("<rule>.<figure>") has them
DEFECT_RULES = {
    "starring": ("starring", ("layers", "margin_min", "margin_radius", "packet_margin",
                              "strength_margin", "mode", "zone_from_core", "zone_to_core"),
                 ("verdict", "criterion", "interlayers")),
    "slip": ("interlayer_slip", ("layers", "margin_min", "margin_radius", "capstan_layers"),
             ("verdict",)),
    "hoop_compression": ("hoop_compression",
                         ("layers", "min_sigma_theta", "min_sigma_theta_radius"), ("verdict",)),
    "pressure": ("pressure", ("max_pressure", "max_pressure_radius", "limit", "ratio"),
                 ("verdict",)),
    "core": ("core", ("core_pressure", "rating", "ratio"), ("verdict",)),
}
# Result.defects figure -> the /defects/<group> attribute, where the two names differ
H5_FIGURE_NAMES = {"margin_min": "min_margin", "margin_radius": "min_margin_radius"}


def defects_of(report):
    """A defect report (pointer) as Result.defects: {rule: {"verdict": "ok", ...}}."""
    out = {}
    for rule, (_, numbers, texts) in DEFECT_RULES.items():
        d = {k: float(_lib.rs_defect_report_value(report, f"{rule}.{k}".encode()))
             for k in numbers}
        d.update({k: _lib.rs_defect_report_text(report, f"{rule}.{k}".encode()).decode()
                  for k in texts})
        out[rule] = d
    return out


def defects_from_file(has, number, text, base=""):
    """Result.defects from a file's /defects groups under `base`, read through
    has(path), number(path, attr) and text(path, attr); {} for a file without them."""
    out = {}
    for rule, (group, numbers, texts) in DEFECT_RULES.items():
        g = f"{base}/defects/{group}"
        if not has(g):
            continue
        d = {k: number(g, H5_FIGURE_NAMES.get(k, k)) for k in numbers}
        d.update({k: text(g, k) for k in texts})
        out[rule] = d
    if "starring" in out and out["starring"]["criterion"] == "" \
            and out["starring"]["verdict"] != "not assessed":
        out["starring"]["criterion"] = "none"
    return out


@dataclass(eq=False)
class Storage:
    """The roll through its storage stages (docs/storage.md); S = stages + 1, stage 0 the
    wound roll, N layers:

    hours          h, storage time at the end of each stage, cumulative (S)
    temperature    C (S)
    humidity       % RH (S)
    core_pressure  Pa (S)
    sigma_r        Pa, S x N, each layer's radial stress at the end of each stage
    sigma_theta    Pa, S x N
    defects        per stage the defect verdicts as Result.defects has them (a run
                   read from a file: empty, the file keeps the verdicts of the wound roll)
    """

    hours: np.ndarray
    temperature: np.ndarray
    humidity: np.ndarray
    core_pressure: np.ndarray
    sigma_r: np.ndarray
    sigma_theta: np.ndarray
    defects: list = field(default_factory=list)

    @property
    def stages(self):
        """Storage stages after the winding (S - 1)."""
        return int(self.hours.shape[0]) - 1

    @property
    def pressure(self):
        """Pa, S x N interlayer pressure, 0 - sigma_r."""
        return 0.0 - self.sigma_r


@dataclass(eq=False)
class History:
    """The roll at stages of the winding (output.history_every; the last is the final
    reel): layers (layers wound at each stage), outer_radius (m), sigma_r and sigma_theta
    (Pa, S x N, NaN for layers not yet wound)."""

    layers: np.ndarray
    outer_radius: np.ndarray
    sigma_r: np.ndarray
    sigma_theta: np.ndarray


def _copy(ptr, n, shape=None):
    if not ptr or n <= 0:
        return np.empty(0)
    a = np.ctypeslib.as_array(ptr, shape=(n,)).copy()
    return a.reshape(shape) if shape else a


def _storage_of(sr, n_layers):
    S = _storage_stages(sr)
    n = _c.c_int(0)

    def arr(name, two_d=False):
        p = _storage_array[name](sr, _c.byref(n))
        return _copy(p, n.value, (S, n_layers) if two_d else None)

    return Storage(hours=arr("hours"), temperature=arr("temperature"), humidity=arr("humidity"),
                   core_pressure=arr("core_pressure"), sigma_r=arr("sigma_r", True),
                   sigma_theta=arr("sigma_theta", True),
                   defects=[defects_of(_storage_defects(sr, s)) for s in range(S)])


def _history_of(res, n_layers):
    S = _lib.rs_reel_result_n_stages(res)
    if S <= 0:
        return None
    n = _c.c_int(0)
    lay = _lib.rs_reel_result_stage_layers(res, _c.byref(n))
    layers = np.array([lay[i] for i in range(n.value)], dtype=np.int64)
    radius = _copy(_stage_array["radius"](res, _c.byref(n)), n.value)
    sr = _copy(_stage_array["sigma_r"](res, _c.byref(n)), n.value, (S, n_layers))
    st = _copy(_stage_array["sigma_theta"](res, _c.byref(n)), n.value, (S, n_layers))
    return History(layers=layers, outer_radius=radius, sigma_r=sr, sigma_theta=st)


def extras(scene, res, n_layers, fail):
    """defects, storage (the scene's stages wound, as `reelsim run` does; None without)
    and history of a wound result, as Result's keyword arguments. `fail(status)` raises
    for a failed call (the library's message)."""
    problem = _scene_problem(scene)
    out = {"history": _history_of(res, n_layers)}
    rep = _VP()
    st = _lib.rs_scene_assess_defects(scene, res, _c.byref(rep))
    try:
        if st != _lib.RS_OK:
            fail(st)
        out["defects"] = defects_of(rep)
    finally:
        _defect_destroy(_c.byref(rep))
    out["storage"] = None
    if _storage_requested(problem):
        sr = _VP()
        st = _storage_run(problem, res, _c.byref(sr))
        try:
            if st != _lib.RS_OK:
                fail(st)
            out["storage"] = _storage_of(sr, n_layers)
        finally:
            _storage_destroy(_c.byref(sr))
    return out
