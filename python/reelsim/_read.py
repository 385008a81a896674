"""reelsim.read: a reelsim HDF5 run file (docs/output.md) into a Result, with h5py."""

import os

import numpy as np

from ._errors import InputError
from ._result import Result


def _text(v):
    return v.decode("utf-8", "replace") if isinstance(v, bytes) else str(v)


def read(path):
    """Reads the run file `path` (written by `reelsim run` or rs_output_write) into a
    Result: /layers/radius, /layers/wound_on_tension, /layers/web_tension,
    /layers/nip_load, /final/sigma_r, /final/sigma_theta, /final/pressure,
    /final/core_pressure and the root attributes wall_seconds and title. Raises
    InputError when the file is not there or is not a run file (a compare or study file
    has no /layers at its root)."""
    import h5py  # only reading needs it

    p = os.fspath(path)
    try:
        f = h5py.File(p, "r")
    except OSError as e:
        raise InputError(f"{p}: cannot read as HDF5 ({e})", "input") from None
    with f:
        need = ("layers/radius", "layers/wound_on_tension", "final/sigma_r",
                "final/sigma_theta", "final/pressure", "final/core_pressure")
        for k in need:
            if k not in f:
                raise InputError(f"{p}: not a reelsim run file (no /{k})", "input")

        def arr(k):
            return np.asarray(f[k][()], dtype=np.float64) if k in f else np.empty(0)

        return Result(radius=arr("layers/radius"), sigma_r=arr("final/sigma_r"),
                      sigma_theta=arr("final/sigma_theta"), pressure=arr("final/pressure"),
                      wound_on_tension=arr("layers/wound_on_tension"),
                      core_pressure=float(f["final/core_pressure"][()]),
                      wall_seconds=float(f.attrs.get("wall_seconds", np.nan)),
                      web_tension=arr("layers/web_tension"), nip_load=arr("layers/nip_load"),
                      title=_text(f.attrs.get("title", "")),
                      air_film=arr("layers/air_film"),
                      air_film_entrained=arr("layers/air_film_entrained"),
                      at_speed_sigma_r=arr("final_at_speed/sigma_r"),
                      at_speed_sigma_theta=arr("final_at_speed/sigma_theta"),
                      at_speed_core_pressure=float(f["final_at_speed/core_pressure"][()])
                      if "final_at_speed/core_pressure" in f else float("nan"),
                      defects=_defects(f))


def _defects(f):
    """Result.defects from the file's /defects groups ({} when it has none)."""
    from ._stored import defects_from_file

    def number(g, k):
        a = f[g].attrs
        return float(a[k]) if k in a else float("nan")

    def text(g, k):
        a = f[g].attrs
        return _text(a[k]) if k in a else ""

    return defects_from_file(lambda g: g.lstrip("/") in f, number, text)
