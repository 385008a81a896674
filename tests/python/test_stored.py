"""Storage, defects and history in Python (docs/python.md): reelsim.run winds the storage
stages a scene asks for as `reelsim run` does, Result carries the stages, the defect
verdicts and the history, and reelsim.read reads run, compare, sweep and optimize files
into the same values the files hold (compared with h5py, an independent reader)."""

import h5py
import numpy as np

from conftest import cli, cli_run, scene

STORAGE = scene("cases/pet-storage.yaml")
RIDER = scene("cases/newsprint-rider.yaml")
SMALL = ["--set", "winding.final_radius=0.1"]
SETS = {"winding.final_radius": 0.1}


def test_run_winds_storage_as_the_cli(reelsim, tmp_path):
    out = tmp_path / "s.h5"
    cli_run(STORAGE, out, *SMALL)
    r = reelsim.run(STORAGE, SETS)
    assert r.storage is not None and r.storage.stages == 5
    with h5py.File(out, "r") as f:
        for k in ("hours", "temperature", "humidity", "core_pressure", "sigma_r", "sigma_theta"):
            assert np.array_equal(getattr(r.storage, k), f["storage/" + k][()]), k
        assert r.defects["core"]["verdict"] == f["defects/core"].attrs["verdict"].decode()
        assert r.defects["core"]["core_pressure"] == f["defects/core"].attrs["core_pressure"]
    # stage 0 is the wound roll
    assert r.storage.core_pressure[0] == r.core_pressure
    assert np.array_equal(r.storage.sigma_r[0], r.sigma_r)
    assert len(r.storage.defects) == 6 and r.storage.defects[0]["core"] == r.defects["core"]
    # read() gives the same stages back
    back = reelsim.read(out)
    assert np.array_equal(back.storage.sigma_theta, r.storage.sigma_theta)
    assert back.defects["hoop_compression"]["verdict"] == r.defects["hoop_compression"]["verdict"]


def test_without_storage_none_and_history(reelsim, tmp_path):
    out = tmp_path / "h.h5"
    cli_run(RIDER, out, *SMALL, "--set", "output.history_every=100")
    r = reelsim.run(RIDER, {**SETS, "output.history_every": 100})
    assert r.storage is None
    assert set(r.defects) == {"hoop_compression", "starring", "pressure", "slip", "core"}
    assert r.defects["pressure"]["verdict"] in ("ok", "risk", "not assessed")
    with h5py.File(out, "r") as f:
        assert np.array_equal(r.history.layers, f["history/layers"][()])
        assert np.array_equal(r.history.sigma_r, f["history/sigma_r"][()], equal_nan=True)
    back = reelsim.read(out)
    assert back.storage is None
    assert np.array_equal(back.history.outer_radius, r.history.outer_radius)
    assert reelsim.run(RIDER, SETS).history is None


def test_read_compare(reelsim, tmp_path):
    out = tmp_path / "c.h5"
    p = cli("compare", STORAGE, "--variant", "lo: winding.tension=100", "--variant", "base",
            RIDER, *SMALL, "-o", str(out), "-q")
    assert p.returncode == 0, p.stderr
    runs = reelsim.read(out)
    assert [x.name for x in runs] == ["1-lo", "2-base", "3-newsprint-rider"]
    r = reelsim.run(STORAGE, SETS)
    assert np.array_equal(runs[1].storage.core_pressure, r.storage.core_pressure)
    assert np.array_equal(runs[1].sigma_r, r.sigma_r)
    assert runs[0].wound_on_tension[0] == 100.0 and runs[2].storage is None
    assert runs[1].defects["core"]["verdict"] == r.defects["core"]["verdict"]


def test_read_sweep_and_optimize(reelsim, tmp_path):
    sw = tmp_path / "sw.h5"
    p = cli("sweep", STORAGE, *SMALL, "--vary", "winding.tension=100,150", "-o", str(sw), "-q")
    assert p.returncode == 0, p.stderr
    s = reelsim.read(sw)
    assert s.parameters == ["winding.tension"] and s.values[:, 0].tolist() == [100.0, 150.0]
    r = reelsim.run(STORAGE, SETS)
    assert s.figures["storage_core_pressure"][1] == r.storage.core_pressure[-1]
    assert s.figures["storage_max_core_pressure"][1] == r.storage.core_pressure.max()
    with h5py.File(sw, "r") as f:
        assert sorted(s.figures) == sorted(f["sweep/figures"])
    best = tmp_path / "best.yaml"
    p = cli("optimize", STORAGE, *SMALL, "--vary", "winding.tension=80:200", "--maximize",
            "winding.tension", "--subject-to", "storage_max_core_pressure<=400e3",
            "-o", str(best), "-q")
    assert p.returncode == 0, p.stderr
    o = reelsim.read(tmp_path / "best.h5")
    assert o.objective == "winding.tension" and o.sense == "maximize"
    assert o.constraints == ["storage_max_core_pressure <= 400000"]
    assert o.figures["storage_max_core_pressure"][o.best] <= 400e3
    assert o.values[o.best, 0] == o.values[:, 0][o.figures["status"] == 0].max() or \
        o.figures["storage_max_core_pressure"][o.values[:, 0].argmax()] > 400e3
