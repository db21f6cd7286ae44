#!/usr/bin/env python3
"""The camera framing of scripts/render_paraview.py (no ParaView needed, numpy is): synthetic
runs with known extents.
  - a sphere of radius R (the shell at rest, a wire inside): the default camera (scale 1);
  - the same sphere drawn out to 2 R along x and 2.5 R down along z (a soft thin shell pulled by
    the wire): a scale at which every point is in the picture, and 1 % less at which one is not;
  - one run, one framing: the largest of its snapshots', whichever snapshot is drawn;
  - a shell drawn out sideways (2.2 R along x) stays clear of the colour bars, x in [0.12, 0.88]
    of the picture's width, where the picture's full width (the former framing) put it under
    them.
Exit 77 (ctest: skipped) without numpy; WIREPACK_PARAVIEW_REQUIRED=1 fails instead.
  tests/paraview/test_framing.py [SOURCE_DIR]"""
import os
import sys

try:
    import numpy as np
except ImportError:
    if os.environ.get("WIREPACK_PARAVIEW_REQUIRED") == "1":
        sys.exit("test_framing: FAIL: numpy is not installed (scripts/install_paraview.sh)")
    print("test_framing: SKIP: numpy is not installed")
    sys.exit(77)

src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
sys.path.insert(0, os.path.join(src, "scripts"))
import render_paraview as rp  # noqa: E402

R = 0.01
ASPECT = 1200 / 900


def sphere(n=400, radius=R):
    """n points on a sphere (Fibonacci lattice) [m]."""
    k = np.arange(n) + 0.5
    z = 1 - 2 * k / n
    phi = np.pi * (1 + 5**0.5) * k
    rr = np.sqrt(1 - z * z)
    return radius * np.column_stack([rr * np.cos(phi), rr * np.sin(phi), z])


class FakeRun:
    """The part of render_paraview.Run that framing() reads: len, R, snapshot(k)."""

    def __init__(self, shells):
        self.R = R
        self.shells = shells

    def __len__(self):
        return len(self.shells)

    def snapshot(self, k):
        wire = np.array([[0.0, 0.0, -R], [0.0, 0.0, 0.0]])
        return wire, np.zeros(2), float(k), {"x": self.shells[k]}


def check(cond, msg):
    if not cond:
        sys.exit("test_framing: FAIL: " + msg)


rest = sphere()
s = rp.framing(FakeRun([rest]), ASPECT)
check(s == 1.0, "a sphere of radius R needs the default camera, got scale %.2f" % s)
check(rp.fits(rest, 1.0, R, ASPECT), "the sphere does not fit the default camera")

drawn = rest * np.array([2.0, 1.0, 1.0])
drawn[drawn[:, 2] < 0, 2] *= 2.5
s = rp.framing(FakeRun([drawn]), ASPECT)
check(1.5 < s < 4.0, "the drawn-out shell: scale %.2f, expected between 1.5 and 4" % s)
check(rp.fits(drawn, s, R, ASPECT), "the drawn-out shell does not fit at its own scale")
check(not rp.fits(drawn, s - 0.01, R, ASPECT), "scale %.2f is not the smallest" % s)

both = rp.framing(FakeRun([rest, drawn, rest]), ASPECT)
check(both == s, "one run, one framing: %.2f against %.2f" % (both, s))


def screen_x(points, scale):
    """Where points fall across the picture, 0 (left edge) to 1 (right edge)."""
    forward, up, right = rp.camera_axes()
    v = np.asarray(points) - scale * R * np.asarray(rp.CAMERA_POSITION)
    t = np.tan(np.radians(rp.VIEW_ANGLE / 2))
    return 0.5 + 0.5 * (v @ right) / (ASPECT * t * (v @ forward))


side = rest * np.array([2.2, 1.0, 1.0])
s_side = rp.framing(FakeRun([side]), ASPECT)
x = screen_x(side, s_side)
check(x.min() >= 0.12 - 1e-9 and x.max() <= 0.88 + 1e-9,
      "sideways shell at scale %.3f spans x %.3f to %.3f of the width, into the colour bars"
      % (s_side, x.min(), x.max()))
s_full = rp.framing(FakeRun([side]), ASPECT, side=0.97)
x = screen_x(side, s_full)
check(x.max() > 0.89, "with the full width the sideways shell reaches only x = %.3f" % x.max())
print("test_framing: ok (drawn-out shell: scale %.2f)" % s)
