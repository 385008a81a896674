"""reelsim.run is interruptible (issue 36): SIGINT to a Python process winding a long reel
(13 s uninterrupted) raises KeyboardInterrupt within a second, through the library's
progress callback; a handler the caller installed is called instead (the run stops
with reelsim.Error, status "interrupted"); afterwards the
caller's handler is back in place and another run works."""

import os
import signal
import subprocess
import sys
import time

from conftest import scene

CHILD = r"""
import signal, sys, time
import reelsim
LONG = {"winding.final_radius": 3, "numerics.reuse": "none", "numerics.rtol": 1e-9}
mode = sys.argv[2]
seen = []
if mode == "custom":
    signal.signal(signal.SIGINT, lambda s, f: seen.append(s))
before = signal.getsignal(signal.SIGINT)
print("ready", flush=True)
t = time.monotonic()
try:
    reelsim.run(sys.argv[1], LONG)
    print("finished", flush=True)
except KeyboardInterrupt:
    print("KeyboardInterrupt", flush=True)
except reelsim.Error as e:
    print("Error " + str(e.status), flush=True)
print("after %.3f" % (time.monotonic() - t), flush=True)
print("custom called" if seen == [signal.SIGINT] else "custom not called", flush=True)
print("handler restored" if signal.getsignal(signal.SIGINT) is before else "handler changed",
      flush=True)
r = reelsim.run(sys.argv[1], {"winding.final_radius": 0.2})
print("again %d" % r.layers, flush=True)
"""


def interrupt(mode):
    p = subprocess.Popen([sys.executable, "-c", CHILD, scene("cases/newsprint-rider.yaml"), mode],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "ready"
    time.sleep(1.0)
    t0 = time.monotonic()
    p.send_signal(signal.SIGINT)
    out = [p.stdout.readline().strip()]  # the line printed right after the run returned
    took = time.monotonic() - t0
    out += p.stdout.read().split("\n")  # (communicate would lose what readline buffered)
    err = p.stderr.read()
    p.wait(timeout=60)
    print(out, err, "took %.3f s" % took)
    assert p.returncode == 0, err
    return out, took


def test_keyboard_interrupt_within_a_second():
    out, took = interrupt("default")
    assert out[0] == "KeyboardInterrupt"
    assert took < 1.0
    assert "custom not called" in out and "handler restored" in out
    assert any(x.startswith("again ") and int(x.split()[1]) > 1000 for x in out)


def test_callers_handler_called():
    out, took = interrupt("custom")
    # the caller's handler ran and did not raise: the run stopped all the same, an Error
    # with status "interrupted" (a partial reel is no result)
    assert out[0] == "Error interrupted"
    assert "custom called" in out and "handler restored" in out
    assert took < 1.0
