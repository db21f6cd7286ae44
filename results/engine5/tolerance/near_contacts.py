#!/usr/bin/python3
# Segment pairs of the wire closer than 2 r (1 + gap) at a run file's last snapshot, for gaps
# 0 (overlapping) to 0.2 r: how many strands touch or nearly touch. Pairs of segments at least 3
# apart along the wire. Usage: near_contacts.py RUN.h5 ... > contacts.csv (needs python3-h5py).
import sys

import h5py
import numpy as np

GAPS = (0, 0.01, 0.05, 0.1, 0.2)


def segment_distances(p0, p1, q0, q1):
    """Closest distances between segments p0-p1 and q0-q1, row by row ((m, 3) arrays)."""
    d1, d2, w = p1 - p0, q1 - q0, p0 - q0
    a, e = (d1 * d1).sum(1), (d2 * d2).sum(1)
    b, c, f = (d1 * d2).sum(1), (d1 * w).sum(1), (d2 * w).sum(1)
    den = a * e - b * b
    safe = np.where(den > 1e-30, den, 1.0)
    s = np.where(den > 1e-30, np.clip((b * f - c * e) / safe, 0, 1), 0.0)
    t = (b * s + f) / e
    s = np.where(t < 0, np.clip(-c / a, 0, 1), np.where(t > 1, np.clip((b - c) / a, 0, 1), s))
    t = np.clip(t, 0, 1)
    return np.linalg.norm(p0 + d1 * s[:, None] - q0 - d2 * t[:, None], axis=1)


print("run,l,nodes," + ",".join(f"gap_{g}r" for g in GAPS))
for name in sys.argv[1:]:
    with h5py.File(name, "r") as f:
        last = max(f["snapshots"].keys(), key=int)
        x = f["snapshots"][last]["wire"][:]
        r = 0.5e-3  # the scenes' wire radius [m]
        l = f["snapshots"][last].attrs.get("l", float("nan"))
    i, j = np.triu_indices(len(x) - 1, 3)
    d = segment_distances(x[i], x[i + 1], x[j], x[j + 1])
    counts = ",".join(str(int((d < 2 * r * (1 + g)).sum())) for g in GAPS)
    print(f"{name.split('/')[-1].rsplit('.', 1)[0]},{float(l):.2f},{len(x)},{counts}")
