"""The examples in examples/python run and draw: two_tapers.py writes a PNG with both
tapers' curves in it, nip_load_loop.py prints one row per nip load whose wound-on tension
is the friction model's closed form T0 = T + mu N (Good, Wu & Fikes 1994; T = 350 N/m,
mu = 0.19) and whose core pressure grows with the load, and draws its PNG."""

import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import SOURCE

EXAMPLES = os.path.join(SOURCE, "examples", "python")


def run_example(name, *args):
    p = subprocess.run([sys.executable, os.path.join(EXAMPLES, name), *map(str, args)],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return p.stdout


def check_png(path, min_bytes=10_000):
    """A real picture: the PNG signature, a sensible size, more than one colour drawn."""
    assert os.path.isfile(path)
    assert os.path.getsize(path) > min_bytes, os.path.getsize(path)
    with open(path, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    import matplotlib.image
    img = matplotlib.image.imread(path)
    assert img.shape[0] >= 300 and img.shape[1] >= 400, img.shape
    assert len(np.unique(img.reshape(-1, img.shape[-1]), axis=0)) > 10


def test_two_tapers(tmp_path):
    png = tmp_path / "tapers.png"
    out = run_example("two_tapers.py", png)
    check_png(png)
    lines = [x for x in out.splitlines() if "core pressure" in x]
    assert len(lines) == 2 and "linear" in lines[0] and "hyperbolic" in lines[1]


def test_nip_load_loop(tmp_path):
    png = tmp_path / "nip.png"
    out = run_example("nip_load_loop.py", png)
    check_png(png)
    rows = [tuple(map(float, x.split())) for x in out.splitlines()[1:]]
    assert len(rows) == 5
    loads, core, wot = (np.array(c) for c in zip(*rows))
    np.testing.assert_allclose(wot, 350.0 + 0.19 * loads, rtol=1e-12, atol=0)
    assert np.all(np.diff(core) > 0)


def test_nip_load_loop_without_png():
    out = run_example("nip_load_loop.py")
    assert len(out.splitlines()) == 6
