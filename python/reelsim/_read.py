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


# Result.defects keys -> /defects attributes (docs/output.md)
_H5_NAMES = {"margin_min": "min_margin", "margin_radius": "min_margin_radius"}


def _defects(f):
    """The starring and slip verdicts of /defects as Result.defects ({} when the file
    predates the starring rule)."""
    if "defects/starring" not in f or "defects/interlayer_slip" not in f:
        return {}
    from ._run import _SLIP, _STARRING

    def group(g, nums, texts):
        a = f[g].attrs
        out = {k: float(a[_H5_NAMES.get(k, k)]) if _H5_NAMES.get(k, k) in a else float("nan")
               for k in nums}
        out.update({k: _text(a[k]) if k in a else "" for k in texts})
        return out

    star = group("defects/starring", _STARRING, ("verdict", "criterion", "interlayers"))
    slip = group("defects/interlayer_slip", _SLIP, ("verdict",))
    if star["criterion"] in ("", "none") and star["verdict"] != "not assessed":
        star["criterion"] = "none"
    return {"starring": star, "slip": slip}
