"""reelsim.run equals the CLI: `reelsim run SCENE -o X.h5` read back with reelsim.read
(h5py) against reelsim.run(SCENE) in this process, array by array, to round-off; the same
with --set overrides; a scene given as YAML text winds as its file does; the version is
the library's and the program's."""

import os

import numpy as np
import pytest

from conftest import cli, cli_run, scene

ARRAYS = ("radius", "sigma_r", "sigma_theta", "pressure", "wound_on_tension", "web_tension",
          "nip_load")


def assert_same(a, b, rtol=1e-12):
    """Every array and the core pressure equal to round-off (both come from the same
    library: in practice bit for bit)."""
    for k in ARRAYS:
        x, y = getattr(a, k), getattr(b, k)
        assert x.dtype == np.float64 and y.dtype == np.float64, k
        assert x.shape == y.shape and x.shape[0] > 0, k
        np.testing.assert_allclose(x, y, rtol=rtol, atol=0, err_msg=k)
    np.testing.assert_allclose(a.core_pressure, b.core_pressure, rtol=rtol, atol=0)


@pytest.mark.parametrize("path", ["cases/newsprint-taper.yaml",     # hyperbolic taper
                                  "cases/newsprint-rider.yaml",     # friction nip
                                  "cases/pet-topweb.yaml",
                                  "tests/cli/scenes/small.yaml"])   # linear law
def test_run_equals_cli_file(reelsim, tmp_path, path):
    out = tmp_path / "x.h5"
    cli_run(scene(path), out)
    from_file = reelsim.read(out)
    r = reelsim.run(scene(path))
    assert_same(r, from_file)
    assert r.title == from_file.title and r.title
    assert r.layers == from_file.layers
    assert np.isfinite(r.wall_seconds) and r.wall_seconds > 0
    # identities of the result itself
    assert np.array_equal(r.pressure, 0.0 - r.sigma_r)
    assert np.all(np.diff(r.radius) > 0)
    assert r.core_pressure > 0


def test_sets_equal_cli(reelsim, tmp_path):
    path = scene("tests/cli/scenes/small.yaml")
    out = tmp_path / "s.h5"
    cli_run(path, out, "--set", "winding.tension=150", "--set", "winding.final_radius=0.065")
    want = reelsim.read(out)
    as_dict = reelsim.run(path, sets={"winding.tension": 150, "winding.final_radius": 0.065})
    as_list = reelsim.run(path, sets=["winding.tension=150", "winding.final_radius=0.065"])
    assert_same(as_dict, want)
    assert_same(as_list, want)
    plain = reelsim.run(path)
    assert as_dict.layers < plain.layers       # the override took effect
    assert as_dict.radius[-1] == pytest.approx(0.065, abs=1.1e-4)  # within a caliper


def test_text_winds_as_its_file(reelsim):
    path = scene("tests/cli/scenes/small.yaml")
    with open(path) as f:
        text = f.read()
    from_path = reelsim.run(path)
    from_text = reelsim.run(text)
    assert_same(from_text, from_path, rtol=0)
    # one line of flow YAML: no newline, no such file, a colon: text
    flow = ("{title: flow, material: {name: w, caliper: 100.0e-6, E_theta: 4.0e9, "
            "radial: {law: linear, E_r: 20.0e6}}, core: {radius: 0.05}, "
            "winding: {final_radius: 0.07, tension: 200}}")
    assert not os.path.exists(flow)
    from_flow = reelsim.run(flow)
    assert_same(from_flow, from_path, rtol=0)
    assert from_flow.title == "flow"
    # a pathlib.Path is a path
    import pathlib
    assert_same(reelsim.run(pathlib.Path(path)), from_path, rtol=0)


def test_version_is_the_librarys(reelsim):
    p = cli("--version")
    assert p.returncode == 0, p.stderr
    assert p.stdout.split()[1] == reelsim.__version__
    assert reelsim.__version__.count(".") == 2
    from reelsim import _lib
    assert _lib.rs_version().decode() == reelsim.__version__


def test_set_values_arrive_exactly(reelsim):
    """A float override reaches the scene as the same double (numpy floats too), ints and
    strings as written."""
    import numpy as np
    path = scene("tests/cli/scenes/small.yaml")
    t = 0.1 + 0.2                                    # 0.30000000000000004, not 0.3
    a = reelsim.run(path, sets={"winding.final_radius": 0.06 + t / 1000})
    b = reelsim.run(path, sets={"winding.final_radius": np.float64(0.06 + t / 1000)})
    c = reelsim.run(path, sets=[f"winding.final_radius={0.06 + t / 1000!r}"])
    assert_same(a, b, rtol=0)
    assert_same(a, c, rtol=0)
