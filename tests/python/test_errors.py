"""Bad input raises reelsim.InputError with the message the CLI prints (without its
"reelsim: " prefix; the CLI exits 2 there), a solver failure raises SolverError with the
CLI's message, and nothing is left behind: the next run in the same thread works."""

import os

import pytest

from conftest import cli, scene

BAD = ["bad-key.yaml", "bad-type.yaml", "missing-key.yaml", "bad-caliper.yaml",
       "bad-no-model.yaml", "bad-radius.yaml", "bad-syntax.yaml", "bad-taper.yaml",
       "bad-model.yaml", "no-such-scene.yaml"]


def cli_message(*args, status):
    p = cli("run", *args, "-o", os.devnull + ".never.h5", "--quiet")
    assert p.returncode == status, (p.returncode, p.stderr)
    assert p.stderr.startswith("reelsim: ") and p.stderr.endswith("\n"), p.stderr
    return p.stderr


@pytest.mark.parametrize("name", BAD)
def test_input_error_is_the_cli_message(reelsim, name):
    path = scene("tests/cli/scenes/" + name)
    want = cli_message(path, status=2)
    with pytest.raises(reelsim.InputError) as e:
        reelsim.run(path)
    assert "reelsim: " + str(e.value) + "\n" == want
    assert e.value.status == "input"
    assert isinstance(e.value, reelsim.Error)
    assert ".yaml" in str(e.value)               # names a file (the scene or its model)


def test_bad_set_is_the_cli_message(reelsim):
    path = scene("tests/cli/scenes/small.yaml")
    want = cli_message(path, "--set", "numerics.rtol=abc", status=2)
    with pytest.raises(reelsim.InputError) as e:
        reelsim.run(path, sets={"numerics.rtol": "abc"})
    assert "reelsim: " + str(e.value) + "\n" == want
    assert "numerics.rtol" in str(e.value)


def test_text_error_names_the_given_name(reelsim):
    path = scene("tests/cli/scenes/bad-key.yaml")
    want = cli_message(path, status=2)
    with open(path) as f:
        text = f.read()
    with pytest.raises(reelsim.InputError) as e:
        reelsim.run(text, name=path)
    assert "reelsim: " + str(e.value) + "\n" == want
    with pytest.raises(reelsim.InputError) as e:
        reelsim.run(text)
    assert str(e.value).startswith("<text>:4: core.radus: unknown key")


def test_solver_error_is_the_cli_message(reelsim):
    path = scene("tests/cli/scenes/small.yaml")
    want = cli_message(path, "--set", "numerics.max_steps=1", status=3)
    first = want.splitlines()[0]
    with pytest.raises(reelsim.SolverError) as e:
        reelsim.run(path, sets=["numerics.max_steps=1"])
    assert first == "reelsim: solver failure: " + str(e.value)
    assert e.value.status == "solver"
    # the error record does not leak into the next run
    r = reelsim.run(path)
    assert r.layers == 200
