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
        assert r.title == f.attrs["title"].decode()  # fixed-length: h5py gives bytes
        assert r.complete and f.attrs["complete"] == 1
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
    with pytest.raises(reelsim.InputError, match="cannot open .*absent.h5"):
        reelsim.read(tmp_path / "absent.h5")
    text = tmp_path / "text.h5"
    text.write_text("not HDF5\n")
    with pytest.raises(reelsim.InputError, match="is not an HDF5 file"):
        reelsim.read(text)
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["runs/x"] = np.zeros(3)
    with pytest.raises(reelsim.InputError, match="not a reelsim file"):
        reelsim.read(other)
    with h5py.File(other, "a") as f:
        f.attrs["program"] = "reelsim"
    # read() takes a comparison file as a list of runs: this one's run is no run group
    with pytest.raises(reelsim.InputError, match="'/runs/x/"):
        reelsim.read(other)
    with h5py.File(other, "a") as f:
        del f["runs"]
    with pytest.raises(reelsim.InputError, match=r"not a reelsim run file \(no /layers/radius\)"):
        reelsim.read(other)


def test_speed_effects_round_trip(reelsim, tmp_path):
    """Entrained air and the centrifugal load: run and read give the same films and the
    same spinning profile, the file's datasets; a scene without them has empty ones."""
    text = ("material: {caliper: 70e-6, E_theta: 3.5e9, density: 800, "
            "radial: {law: pfeiffer, K1: 5e3, K2: 60}}\ncore: {radius: 0.0762}\n"
            "winding: {final_radius: 0.1, tension: 350, speed: 20}\n"
            "centrifugal: {}\nair: {roughness: 0.5e-6}\n")
    path = tmp_path / "speed.yaml"
    path.write_text(text)
    out = tmp_path / "speed.h5"
    cli_run(str(path), out)
    a, b = reelsim.run(str(path)), reelsim.read(out)
    with h5py.File(out, "r") as f:
        for k, p in {"air_film": "layers/air_film",
                     "air_film_entrained": "layers/air_film_entrained",
                     "at_speed_sigma_r": "final_at_speed/sigma_r",
                     "at_speed_sigma_theta": "final_at_speed/sigma_theta"}.items():
            assert np.array_equal(getattr(a, k), f[p][()]), k
            assert np.array_equal(getattr(b, k), f[p][()]), k
        assert a.at_speed_core_pressure == f["final_at_speed/core_pressure"][()]
    assert a.layers == b.layers and a.air_film.shape == (a.layers,)
    assert np.all(a.air_film > 0) and np.all(a.air_film <= a.air_film_entrained)
    # the radius holds the compressed films: r_c + sum (t + h)
    assert np.isclose(a.radius[-1], 0.0762 + np.sum(70e-6 + a.air_film), rtol=1e-12)
    plain = reelsim.run(text.replace("centrifugal: {}\nair: {roughness: 0.5e-6}\n", ""))
    assert plain.air_film.size == 0 and plain.at_speed_sigma_r.size == 0
    assert np.isnan(plain.at_speed_core_pressure)
