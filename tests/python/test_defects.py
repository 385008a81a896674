"""Result.defects: the starring and cinching verdicts (docs/defects.md) from reelsim.run are
the CLI's JSON summary's and the file's that reelsim.read gives back, on a scene whose
compressed zone slips and buckles under a hard start, and on one where nothing is at risk."""

import json
import math

from conftest import cli, cli_run, scene

SLIPPING = ["core.stiffness=5e7", "material.friction_layer=0.3", "winding.accel_torque=20000",
            "numerics.rtol=1e-3"]


def same(a, b):
    return a == b or (isinstance(a, float) and isinstance(b, float)
                      and math.isnan(a) and math.isnan(b))


def test_run_read_and_json_agree(reelsim, tmp_path):
    path = scene("cases/newsprint-falling-taper.yaml")
    out = tmp_path / "ft.h5"
    sets = [x for s in SLIPPING for x in ("--set", s)]
    cli_run(path, out, *sets)
    a = reelsim.run(path, SLIPPING).defects
    b = reelsim.read(out).defects
    p = cli("run", path, "--json", "-o", str(tmp_path / "j.h5"), *sets)
    assert p.returncode == 0, p.stderr
    j = json.loads(p.stdout)["defects"]
    assert a["starring"]["verdict"] == "risk" and a["starring"]["interlayers"] == "slipping"
    assert a["starring"]["criterion"] == "packet_buckling"
    assert 0.2 < a["starring"]["margin_min"] < 0.3, a["starring"]
    assert a["starring"]["zone_from_core"] == 0.0
    assert a["slip"]["verdict"] == "risk" and a["slip"]["capstan_layers"] == 1
    for rule in ("starring", "slip"):
        assert set(a[rule]) == set(b[rule]), rule
        for k in a[rule]:
            assert same(a[rule][k], b[rule][k]), (rule, k, a[rule][k], b[rule][k])
    for k in ("verdict", "criterion", "margin_min", "margin_radius", "mode", "zone_to_core",
              "interlayers"):
        assert same(a["starring"][k], j["starring"][k]), k
    assert a["slip"]["margin_min"] == j["slip"]["margin_min"]


def test_nothing_at_risk(reelsim):
    d = reelsim.run(scene("cases/pet-topweb.yaml")).defects
    assert d["starring"]["verdict"] == "ok" and d["starring"]["interlayers"] == "bonded"
    assert d["starring"]["margin_min"] > 1.0
    assert d["slip"]["verdict"] == "not assessed" and math.isnan(d["slip"]["margin_min"])
