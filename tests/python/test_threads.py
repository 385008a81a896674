"""Runs in threads do not interfere: two different scenes wound at once in two threads
(three rounds each), and a third thread failing on bad input meanwhile, give each what a
serial run gives, bit for bit, and the failing thread its own message."""

import threading

import numpy as np
import reelsim

from conftest import scene

A = scene("cases/newsprint-rider.yaml")
B = scene("cases/pet-topweb.yaml")
BAD = scene("tests/cli/scenes/bad-key.yaml")
ARRAYS = ("radius", "sigma_r", "sigma_theta", "pressure", "wound_on_tension")


def same(x, y):
    return all(np.array_equal(getattr(x, k), getattr(y, k)) for k in ARRAYS) and \
        x.core_pressure == y.core_pressure


def test_two_scenes_in_threads():
    serial = {A: reelsim.run(A), B: reelsim.run(B)}
    try:
        reelsim.run(BAD)
    except reelsim.InputError as e:
        bad_message = str(e)
    assert "core.radus" in bad_message
    assert not same(serial[A], serial[B]) or serial[A].layers != serial[B].layers

    got, errors = {A: [], B: [], BAD: []}, []
    start = threading.Barrier(3)

    def work(path):
        try:
            start.wait()
            for _ in range(3):
                try:
                    got[path].append(reelsim.run(path))
                except reelsim.InputError as e:
                    got[path].append(str(e))
        except Exception as e:  # noqa: BLE001 (reported below, on the main thread)
            errors.append(repr(e))

    threads = [threading.Thread(target=work, args=(p,)) for p in (A, B, BAD)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    for p in (A, B):
        assert len(got[p]) == 3
        for r in got[p]:
            assert isinstance(r, reelsim.Result)
            assert same(r, serial[p]), p
    assert got[BAD] == [bad_message] * 3
