#!/usr/bin/env python3
"""Two tension tapers on the same newsprint reel, side by side: interlayer pressure and
hoop stress against radius. Usage: two_tapers.py OUT.png

With PYTHONPATH=build/python (a build tree) or the installed package (docs/python.md).
"""

import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

import reelsim  # noqa: E402

SCENE = """\
title: newsprint, two tapers
material: newsprint
core: {radius: 0.0762}
winding:
  final_radius: 0.3
  tension: {law: linear, start: 350, end: 350}
"""

TAPERS = {
    "linear 350 -> 200 N/m": {"winding.tension.law": "linear", "winding.tension.end": 200},
    "hyperbolic 350 -> 200 N/m": {"winding.tension.law": "hyperbolic",
                                  "winding.tension.end": 200},
}


def main(argv):
    if len(argv) != 2:
        print("usage: two_tapers.py OUT.png", file=sys.stderr)
        return 2
    fig, (ax_p, ax_h) = plt.subplots(2, 1, sharex=True, figsize=(7, 7))
    for label, sets in TAPERS.items():
        r = reelsim.run(SCENE, sets=sets)
        mm = r.radius * 1e3
        ax_p.plot(mm, r.pressure / 1e3, label=label)
        ax_h.plot(mm, r.sigma_theta / 1e6, label=label)
        print(f"{label}: {r.layers} layers, core pressure {r.core_pressure / 1e3:.1f} kPa, "
              f"min hoop stress {r.sigma_theta.min() / 1e6:.2f} MPa")
    ax_p.set_ylabel("interlayer pressure (kPa)")
    ax_h.set_ylabel("hoop stress (MPa)")
    ax_h.set_xlabel("radius (mm)")
    ax_h.axhline(0.0, color="grey", lw=0.5)
    ax_p.set_title("newsprint, two tension tapers")
    for ax in (ax_p, ax_h):
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(argv[1], dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
