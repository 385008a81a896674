#!/usr/bin/env python3
"""A loop over nip loads: a rider roll (friction nip model, T0 = T + mu N) pressing
harder on a newsprint reel, printing the core pressure and the wound-on tension (WOT) for
each load and, given a path, plotting them. Usage: nip_load_loop.py [OUT.png]

With PYTHONPATH=build/python (a build tree) or the installed package (docs/python.md).
"""

import sys

import reelsim

SCENE = """\
title: newsprint with a rider roll
material: newsprint
core: {radius: 0.0762, stiffness: 1.0e9}
winding: {final_radius: 0.25, tension: 350}
nip: {model: friction, load: 1000, friction: {roll: 0.19}}
"""

LOADS = [250.0, 500.0, 1000.0, 1750.0, 2500.0]  # N/m


def main(argv):
    rows = []
    print(f"{'nip load N/m':>12} {'core pressure Pa':>17} {'WOT N/m':>9}")
    for load in LOADS:
        r = reelsim.run(SCENE, sets={"nip.load": load})
        wot = float(r.wound_on_tension[-1])  # the same on every layer: constant T and N
        rows.append((load, r.core_pressure, wot))
        print(f"{load:12.1f} {r.core_pressure:17.6e} {wot!r:>9}")
    if len(argv) > 1:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot([x[0] for x in rows], [x[1] / 1e3 for x in rows], "o-", label="core pressure")
        ax.set_xlabel("nip load (N/m)")
        ax.set_ylabel("core pressure (kPa)")
        ax2 = ax.twinx()
        ax2.plot([x[0] for x in rows], [x[2] for x in rows], "s--", color="C1", label="WOT")
        ax2.set_ylabel("wound-on tension (N/m)")
        ax.grid(True, alpha=0.3)
        fig.legend(loc="upper left")
        fig.tight_layout()
        fig.savefig(argv[1], dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
