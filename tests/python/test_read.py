"""reelsim.read gives exactly what the file holds (each array against h5py's own read of
the dataset named in docs/output.md), the same Result as the run that wrote it, and refuses
what is not a run file with InputError."""

import h5py
import numpy as np
import pytest

from conftest import cli_run, scene

PATHS = {"radius": "layers/radius", "wound_on_tension": "layers/wound_on_tension",
         "web_tension": "layers/web_tension", "nip_load": "layers/nip_load",
         "sigma_r": "final/sigma_r", "sigma_theta": "final/sigma_theta",
         "pressure": "final/pressure"}


def test_read_is_the_file(reelsim, tmp_path):
    out = tmp_path / "rider.h5"
    cli_run(scene("cases/newsprint-rider.yaml"), out)
    r = reelsim.read(str(out))
    with h5py.File(out, "r") as f:
        for k, p in PATHS.items():
            assert np.array_equal(getattr(r, k), f[p][()]), k
        assert r.core_pressure == f["final/core_pressure"][()]
        assert r.wall_seconds == f.attrs["wall_seconds"]
        assert r.layers == f.attrs["layers"]
        assert r.title == f.attrs["title"]
    assert np.array_equal(r.pressure, 0.0 - r.sigma_r)
    assert np.all(r.nip_load == 1750.0)          # the scene's nip load on every layer


def test_read_round_trips_a_run(reelsim, tmp_path):
    path = scene("cases/newsprint-taper.yaml")
    out = tmp_path / "taper.h5"
    cli_run(path, out)
    a, b = reelsim.run(path), reelsim.read(out)
    for k in PATHS:
        assert np.array_equal(getattr(a, k), getattr(b, k)), k
    assert a.core_pressure == b.core_pressure


def test_read_refuses(reelsim, tmp_path):
    with pytest.raises(reelsim.InputError, match="cannot read as HDF5"):
        reelsim.read(tmp_path / "absent.h5")
    text = tmp_path / "text.h5"
    text.write_text("not HDF5\n")
    with pytest.raises(reelsim.InputError, match="cannot read as HDF5"):
        reelsim.read(text)
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["runs/x"] = np.zeros(3)
    with pytest.raises(reelsim.InputError, match=r"not a reelsim run file \(no /layers/radius\)"):
        reelsim.read(other)
