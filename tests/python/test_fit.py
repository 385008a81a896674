"""reelsim.fit_stack over the library's fit: the shipped stack test, and a refusal."""
import csv
import os

import numpy as np
import pytest

import reelsim

ROOT = os.environ.get("RS_ROOT", os.path.join(os.path.dirname(__file__), "..", ".."))


def _loading_branch():
    rows = [r for r in csv.reader(open(os.path.join(ROOT, "cases", "data", "stack-test.csv")))
            if r and not r[0].startswith("#")]
    head, rows = rows[0], rows[1:]
    c, e, p = (head.index(k) for k in ("cycle", "strain", "pressure"))
    last = [r for r in rows if r[c] == rows[-1][c]]
    P = np.array([float(r[p]) for r in last])
    peak = int(np.argmax(P))
    return np.array([float(r[e]) for r in last])[:peak + 1], P[:peak + 1]


def test_fit_stack_pfeiffer_brackets_the_truth():
    e, P = _loading_branch()
    f = reelsim.fit_stack(e, P, law="pfeiffer")
    assert f.names == ["K1", "K2"]
    (k1lo, k1hi), (k2lo, k2hi) = f.intervals
    # the file was made from K1 = 8 kPa, K2 = 55 with strain noise 4e-4
    assert k1lo < 8.0e3 < k1hi and k2lo < 55.0 < k2hi
    assert 2e-4 < f.rms < 6e-4


def test_fit_stack_refuses_too_few_points():
    with pytest.raises(reelsim.InputError, match="at least"):
        reelsim.fit_stack([0.01, 0.02], [1e4, 3e4], law="hakiel")
