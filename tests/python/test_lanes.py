"""Result.lanes (docs/lanes.md): reelsim.run gives the lanes' arrays as the CLI's run
file holds them (read with h5py, an independent reader), reelsim.read gives the same, and
a reel without lanes has none."""

import h5py
import numpy as np

from conftest import cli_run, scene

BAND = scene("tests/cli/scenes/lanes/band.yaml")
SMALL = scene("tests/cli/scenes/small.yaml")


def test_run_and_read_give_the_files_lanes(reelsim, tmp_path):
    out = tmp_path / "band.h5"
    cli_run(BAND, out)
    r = reelsim.run(BAND)
    f = reelsim.read(out)
    assert r.lanes is not None and f.lanes is not None
    with h5py.File(out, "r") as h:
        for key, path in (("x", "lanes/x"), ("outer_radius", "lanes/outer_radius"),
                          ("core_pressure", "lanes/core_pressure"),
                          ("web_tension", "lanes/web_tension"),
                          ("wound_on_tension", "lanes/wound_on_tension"),
                          ("final_sigma_r", "lanes/final/sigma_r"),
                          ("final_radius", "lanes/final/radius")):
            assert np.array_equal(r.lanes[key], h[path][()]), key
            assert np.array_equal(f.lanes[key], h[path][()]), key
        assert np.array_equal(r.lanes["slack"], h["lanes/slack"][()] == 1.0)
    assert r.lanes["web_tension"].shape == (r.layers, 3)
    # the 2 % band in the middle lane runs hard
    assert r.lanes["core_pressure"][1] > r.lanes["core_pressure"][0]


def test_no_lanes(reelsim):
    assert reelsim.run(SMALL).lanes is None
