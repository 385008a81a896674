"""Shared by the Python package's tests (tests/python/python.cmake runs each file with
pytest). From the environment: RS_SOURCE (source tree), RS_BUILD (build tree), RS_CLI
(the reelsim program), PYTHONPATH=<build>/python (the package as the build made it)."""

import os
import subprocess

import pytest

SOURCE = os.environ["RS_SOURCE"]
BUILD = os.environ["RS_BUILD"]
CLI = os.environ["RS_CLI"]


def scene(rel):
    """A scene of the source tree: "cases/newsprint-taper.yaml", "tests/cli/scenes/..."."""
    return os.path.join(SOURCE, rel)


def cli(*args, cwd=None):
    """Runs the reelsim program; returns the CompletedProcess (text stdout and stderr)."""
    return subprocess.run([CLI, *args], capture_output=True, text=True, cwd=cwd)


def cli_run(path, out, *args):
    """`reelsim run PATH -o OUT --quiet ARGS...`, which must succeed."""
    p = cli("run", path, "-o", str(out), "--quiet", *args)
    assert p.returncode == 0, p.stderr
    assert os.path.getsize(out) > 0
    return p


@pytest.fixture(scope="session")
def reelsim():
    import reelsim as rs
    # the package under test is the build tree's, not some other installed one
    assert os.path.realpath(rs.__file__).startswith(os.path.realpath(BUILD)), rs.__file__
    return rs
