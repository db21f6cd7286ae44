#!/usr/bin/env python3
"""How near each snapshot's shell comes to the guide, the wire outside the hole on the feed axis
below the pole (the z axis, hole at z = -R): per run file and snapshot, the number of shell
vertices below the pole, the nearest of them to the axis and the lowest, in units of the wire
radius r and the sphere radius R, beside the guide's reach r + t/2 (a face nearer than that to
the axis touches it). A snapshot shows one instant: a run whose snapshots all keep clear may
still have met the guide between them (first_difference.sh on a rerun tells).
  python3 results/paper/guide_clearance.py RUN.h5 [RUN.h5 ...]
Needs h5py and numpy (scripts/install_paraview.sh brings both). CSV on stdout."""
import json
import os
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:
    sys.exit("guide_clearance.py: %s (scripts/install_paraview.sh installs h5py and numpy)" % e)

if len(sys.argv) < 2:
    sys.exit(__doc__)
print("file,l,reach_r,below_pole,nearest_axis_r,lowest_z_R")
for path in sys.argv[1:]:
    with h5py.File(path, "r") as f:
        cfg = json.loads(f.attrs["config"])
        if cfg.get("shell") != "elastic":
            continue
        r = float(cfg["wire"]["radius"])  # [m]
        R = float(cfg["rho"]) * r  # [m]
        t = R / float(cfg["xi"])  # shell thickness [m]
        for k in sorted(f["snapshots"].keys(), key=int):
            g = f["snapshots"][k]
            x = np.asarray(g["shell_vertices"], dtype=float).reshape(-1, 3)  # [m], n x 3
            below = x[:, 2] < -R
            axis = np.hypot(x[below, 0], x[below, 1])  # distance from the feed axis [m]
            nearest = "%.3f" % (axis.min() / r) if below.any() else ""
            print("%s,%.4g,%.3f,%d,%s,%.3f" % (os.path.basename(path), float(g.attrs["l"]),
                                                (r + t / 2) / r, int(below.sum()), nearest,
                                                x[:, 2].min() / R))
