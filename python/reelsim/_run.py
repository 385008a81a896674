"""reelsim.run: load a scene, wind it, and copy the result into numpy arrays.

Every call owns its scene and result (created and destroyed here) and the library's error
record is per thread, read on the calling thread right after the call that failed: runs in
several Python threads do not interfere. ctypes releases the GIL during each foreign call,
so threads wind in parallel.
"""

import ctypes
import os
import signal
import threading

import numpy as np

from . import _lanes, _lib
from ._errors import Error, InputError, SolverError
from ._result import Result
from . import _stored

_ARRAYS = ("radius", "sigma_r", "sigma_theta", "wound_on_tension", "web_tension", "nip_load",
           "air_film", "air_film_entrained", "at_speed_sigma_r", "at_speed_sigma_theta")


def _is_text(scene):
    """A str is YAML text when it has a newline; else a path when such a file exists; else
    text when it has a colon ("{material: newsprint, ...}" on one line); else a path (the
    library then says it cannot open it)."""
    if "\n" in scene:
        return True
    if os.path.isfile(scene):
        return False
    return ":" in scene


def _set_strings(sets):
    """--set overrides: a mapping {"winding.tension": 300} or strings "key=value"."""
    if sets is None:
        return []
    if isinstance(sets, (str, bytes)):
        sets = [sets]
    if hasattr(sets, "items"):
        out = []
        for k, v in sets.items():
            if v is None:
                v = "null"
            elif isinstance(v, bool):
                v = "true" if v else "false"
            elif isinstance(v, float):  # numpy floats too
                v = float.__repr__(float(v))  # shortest round-trip form: the same double
            out.append(f"{k}={v}")
        return out
    return [s.decode() if isinstance(s, bytes) else str(s) for s in sets]


def _raise(status, message):
    if status == _lib.RS_ERR_INPUT:
        raise InputError(message, "input")
    if status == _lib.RS_ERR_SOLVER:
        raise SolverError(message, "solver")
    name = _lib.rs_status_name(status).decode()
    raise Error(f"{name}: {message}", name)


def _last_message():
    return _lib.rs_error_message().decode("utf-8", "replace")


_PROGRESS = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_int, ctypes.c_int)


class _Options(ctypes.Structure):  # rs_reel_options
    _fields_ = [("progress", _PROGRESS), ("user", ctypes.c_void_p)]


class _Interruptible:
    """Ctrl-C during a run (issue 36). The library calls its progress callback after every
    increment; Python runs its signal handlers whenever the main thread executes bytecode,
    so during the callback. While a run is in progress SIGINT only sets a flag, which the
    callback returns (nonzero: the library stops after the increment, RS_ERR_INTERRUPTED);
    the handler the caller had is restored and then honoured (KeyboardInterrupt by
    default). Only on the main thread, where Python delivers signals: other threads run
    without a callback, as before."""

    def __init__(self):
        self.caught = False
        self.old = None
        self.opts = None
        if threading.current_thread() is not threading.main_thread():
            return
        old = signal.getsignal(signal.SIGINT)
        if old in (signal.SIG_IGN, None):
            return
        self.old = old
        signal.signal(signal.SIGINT, self._on_signal)
        self.callback = _PROGRESS(lambda user, done, total: 1 if self.caught else 0)
        self.opts = _Options(self.callback, None)

    def _on_signal(self, signum, frame):
        self.caught = True

    def pointer(self):
        return ctypes.cast(ctypes.pointer(self.opts), ctypes.c_void_p) if self.opts else None

    def restore(self):
        """Puts the caller's handler back; then raises what it would have raised."""
        if self.old is None:
            return
        signal.signal(signal.SIGINT, self.old)
        if self.caught:
            if callable(self.old):
                self.old(signal.SIGINT, None)
            else:  # SIG_DFL: what the default action amounts to for Python code
                raise KeyboardInterrupt


_GET = {k: _lib.result_array(k) for k in _ARRAYS}
_SCALAR = {k: _lib.result_double(k) for k in ("core_pressure", "wall_seconds",
                                              "at_speed_core_pressure")}


def _copy(res, name):
    n = ctypes.c_int(0)
    ptr = _GET[name](res, ctypes.byref(n))
    if n.value == 0 or not ptr:
        return np.empty(0)
    return np.ctypeslib.as_array(ptr, shape=(n.value,)).copy()


def run(scene, sets=None, *, name=None):
    """Winds a scene and returns its Result.

    scene: a path (str or os.PathLike) of a scene file, or the scene's YAML text. A str
      is taken as text when it contains a newline; otherwise as a path when that file
      exists; otherwise as text when it contains a colon; otherwise as a path. Bytes are
      text.
    sets: overrides as the CLI's --set: a mapping {"winding.tension": 300} or a list of
      "key=value" strings.
    name: for text, the file name it stands for in messages and for finding material
      models beside it (default "<text>", models looked up from the current directory).

    Ctrl-C (SIGINT) stops the run after the increment in progress and raises
    KeyboardInterrupt (on the main thread; the caller's own SIGINT handler is honoured).

    Raises InputError (bad scene: the CLI's message, exit status 2 there), SolverError
    (no converged or finite answer, exit status 3) or Error (anything else).
    """
    sets = _set_strings(sets)
    c_sets = (ctypes.c_char_p * max(len(sets), 1))(*[s.encode() for s in sets])
    sc = ctypes.c_void_p()
    if isinstance(scene, bytes):
        text = scene
    elif isinstance(scene, str) and _is_text(scene):
        text = scene.encode()
    else:
        text = None
    if text is None:
        st = _lib.rs_scene_load(os.fsencode(scene), len(sets), c_sets, ctypes.byref(sc))
    else:
        nm = os.fsencode(name) if name is not None else b"<text>"
        st = _lib.rs_scene_load_text(nm, text, len(text), len(sets), c_sets, ctypes.byref(sc))
    if st != _lib.RS_OK:
        msg = _last_message()
        _lib.rs_scene_destroy(ctypes.byref(sc))
        _raise(st, msg)
    res = ctypes.c_void_p()
    try:
        intr = _Interruptible()
        try:
            st = _lib.rs_scene_wind(sc, intr.pointer(), ctypes.byref(res))
        finally:
            intr.restore()  # raises KeyboardInterrupt after a Ctrl-C
        if st != _lib.RS_OK:
            msg = _last_message()
            if st == _lib.RS_ERR_INPUT:  # as the CLI says it: which scene
                msg = f"{_lib.rs_scene_path(sc).decode('utf-8', 'replace')}: {msg}"
            _raise(st, msg)
        what = ctypes.c_char_p()
        if not _lib.rs_reel_result_finite(res, ctypes.byref(what)):
            raise SolverError(f"the {what.value.decode()} is not a finite number", "solver")
        a = {k: _copy(res, k) for k in _ARRAYS}
        more = _stored.extras(sc, res, int(a["radius"].shape[0]),
                              lambda st: _raise(st, _last_message()))
        more["lanes"] = _lanes.of_result(res)
        return Result(**more,
                      radius=a["radius"], sigma_r=a["sigma_r"], sigma_theta=a["sigma_theta"],
                      pressure=0.0 - a["sigma_r"],  # as the HDF5 file: +0 where sigma_r = +0
                      wound_on_tension=a["wound_on_tension"],
                      core_pressure=float(_SCALAR["core_pressure"](res)),
                      wall_seconds=float(_SCALAR["wall_seconds"](res)),
                      web_tension=a["web_tension"], nip_load=a["nip_load"],
                      title=_lib.rs_scene_title(sc).decode("utf-8", "replace"),
                      air_film=a["air_film"], air_film_entrained=a["air_film_entrained"],
                      at_speed_sigma_r=a["at_speed_sigma_r"],
                      at_speed_sigma_theta=a["at_speed_sigma_theta"],
                      at_speed_core_pressure=float(_SCALAR["at_speed_core_pressure"](res)))
    finally:
        _lib.rs_reel_result_destroy(ctypes.byref(res))
        _lib.rs_scene_destroy(ctypes.byref(sc))
