"""The installed package: `cmake --install` of this build into a fresh prefix outside the
trees, then a Python process with PYTHONPATH=<prefix>/lib/python3/dist-packages only (run
from a directory outside the trees, no REELSIM_LIBRARY) imports reelsim from the prefix,
loads the prefix's libreelsim (not the build tree's), finds the installed material model
and winds the reel the build tree's package winds."""

import json
import os
import shutil
import subprocess
import sys

import numpy as np

from conftest import BUILD, SOURCE

PROBE = r"""
import json, sys, reelsim
r = reelsim.run("scene.yaml")
libs = sorted({l.split()[-1] for l in open("/proc/self/maps") if "libreelsim" in l})
print(json.dumps({"file": reelsim.__file__, "version": reelsim.__version__, "libs": libs,
                  "core_pressure": r.core_pressure, "sigma_r": list(r.sigma_r)}))
"""


def test_installed_package_runs(reelsim, tmp_path):
    prefix = tmp_path / "prefix"
    p = subprocess.run([os.environ.get("RS_CMAKE", "cmake"), "--install", BUILD,
                        "--prefix", str(prefix)], capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    site = prefix / "lib" / "python3" / "dist-packages"
    assert (site / "reelsim" / "__init__.py").is_file()
    assert (site / "reelsim" / "_libpath.py").is_file()
    work = tmp_path / "work"
    work.mkdir()
    shutil.copy(os.path.join(SOURCE, "tests", "install", "newsprint-small.yaml"),
                work / "scene.yaml")
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "REELSIM_LIBRARY", "REELSIM_MODELS")}
    env["PYTHONPATH"] = str(site)
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    p = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True,
                       cwd=work, env=env)
    assert p.returncode == 0, p.stderr
    got = json.loads(p.stdout)
    assert got["file"].startswith(str(site)), got["file"]
    assert got["libs"] and all(x.startswith(str(prefix)) for x in got["libs"]), got["libs"]
    assert got["version"] == reelsim.__version__
    want = reelsim.run(os.path.join(SOURCE, "tests", "install", "newsprint-small.yaml"))
    np.testing.assert_allclose(got["sigma_r"], want.sigma_r, rtol=1e-12, atol=0)
    assert got["core_pressure"] == want.core_pressure
