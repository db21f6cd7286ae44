#!/usr/bin/env python3
"""One row per run of the crumpling study's sweeps, and one per (variant, mu_s).

Usage: summary.py WIREPACK OUT_RUNS.csv OUT_POINTS.csv VARIANT=SWEEP_DIR[@L_MAX[@SEEDS[@MUS]]] ...

@L_MAX cuts every series at l = L_MAX (a longer committed sweep read as the protocol's
baseline; its sense blocks then come from its last snapshot <= L_MAX, blank where it has none),
@SEEDS and @MUS keep only those seeds and mu_s values (comma-separated). The runs are the
manifest's and any other finished mu_s-X_sN_ID.h5 in SWEEP_DIR/runs, ordered by mu_s and seed.

Per run (from `wirepack export`): the maximum of D_chord over l in [5, l_end] and the l where
it sits, D_chord at the end, how far from the end D_chord was last above 0.1 (a coil that
turned a block back and in again reads 0 there), U_b hat at the end, the median of E_kin / U
over [5, l_end] (U = U_b + U_t + U_s), steps and wall time, and the sense blocks of the last
snapshot (reversals, order length in R: the longest stretch of one coiling sense).
Per (variant, mu_s): the seed mean, SD and SEM of max D_chord, its distinct outcomes (sorted
per-seed values more than 0.01 apart count as distinct), the runs with order length <= 0.3 l.
Standard library only; the analysis proper is `wirepack analyze`.
"""
import csv
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile


def series(wp, run, tmp):
    out = os.path.join(tmp, "s.csv")
    subprocess.run([wp, "export", run, "--csv", out], check=True, capture_output=True)
    with open(out) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def profile(wp, run, tmp, k):
    """(l, reversals, order length / R) of snapshot k, from the profile's header; None if none."""
    out = os.path.join(tmp, "p.csv")
    r = subprocess.run([wp, "export", run, "--profile", out, "--snapshot", str(k)],
                       capture_output=True)
    if r.returncode != 0:
        return None
    with open(out) as f:
        head = "".join(f.readline() for _ in range(3))
    l = float(re.search(r"l = ([-0-9.eE+]+)", head).group(1))
    rev = float(re.search(r"reversals = ([0-9]+)", head).group(1))
    order = float(re.search(r"order length = ([-0-9.eE+]+) R", head).group(1))
    return l, rev, order


def last_profile(wp, run, tmp, l_max):
    """The sense blocks of the last snapshot at l <= l_max (+0.05); NaNs if there is none.
    (summary.py reads them only where that snapshot is within 0.5 of the series' end.)"""
    best = (math.nan, math.nan, math.nan)
    k = 0
    while True:
        p = profile(wp, run, tmp, k)
        if p is None or p[0] > l_max + 0.05:
            return best
        best = p
        k += 1


def distinct(values, gap=0.01):
    """Number of distinct outcomes: sorted values split where neighbours differ by > gap."""
    xs = sorted(values)
    return 0 if not xs else 1 + sum(1 for a, b in zip(xs, xs[1:]) if b - a > gap)


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    wp, out_runs, out_points = sys.argv[1:4]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for arg in sys.argv[4:]:
            variant, spec = arg.split("=", 1)
            parts = spec.split("@")
            d = parts[0]
            l_max = float(parts[1]) if len(parts) > 1 else math.inf
            seeds = {int(x) for x in parts[2].split(",")} if len(parts) > 2 else None
            mus = {float(x) for x in parts[3].split(",")} if len(parts) > 3 else None
            manifest = json.load(open(os.path.join(d, "manifest.json")))
            runs = sorted(manifest["runs"], key=lambda r: (float(r["point"].get("mu_s", -1)),
                                                           r["seed"]))
            # Finished runs of the folder that the manifest does not list (a sweep resumed with
            # another seed range writes its own list): mu_s and seed from the file name.
            listed = {r["file"] for r in runs}
            for name in sorted(os.listdir(os.path.join(d, "runs"))):
                m = re.match(r"mu_s-([^_]+)_s([0-9]+)_[0-9a-f]{12}\.h5$", name)
                if m and "runs/" + name not in listed:
                    runs.append({"file": "runs/" + name, "seed": int(m.group(2)),
                                 "point": {"mu_s": float(m.group(1))}})
            runs.sort(key=lambda r: (float(r["point"].get("mu_s", -1)), r["seed"]))
            for run in runs:
                path = os.path.join(d, run["file"])
                if not os.path.exists(path) or (seeds and run["seed"] not in seeds):
                    continue
                if mus and float(run["point"].get("mu_s", -1)) not in mus:
                    continue
                s = [r for r in series(wp, path, tmp) if r["l"] <= l_max + 1e-6]
                if not s:
                    continue
                win = [r for r in s if r["l"] >= 5.0]
                end = s[-1]
                top = max(win, key=lambda r: r["D_chord"]) if win else end
                above = [r["l"] for r in win if r["D_chord"] > 0.1]
                ratio = [r["E_kin"] / (r["U_b"] + r["U_t"] + r["U_s"]) for r in win
                         if r["U_b"] + r["U_t"] + r["U_s"] > 0]
                l_snap, rev, order = last_profile(wp, path, tmp, l_max)
                if not abs(l_snap - end["l"]) <= 0.5:  # no snapshot at the end of the series
                    l_snap, rev, order = math.nan, math.nan, math.nan
                rows.append({
                    "variant": variant, "mu_s": run["point"].get("mu_s"),
                    "seed": run["seed"],
                    "l_end": round(end["l"], 3), "max_D_chord": round(top["D_chord"], 5),
                    "l_at_max": round(top["l"], 2), "D_chord_end": round(end["D_chord"], 5),
                    "l_last_above_0.1": round(above[-1], 2) if above else "",
                    "U_b_hat_end": round(end["U_b_hat"], 5),
                    "Ekin_over_U_median": round(statistics.median(ratio), 5) if ratio else "",
                    "steps": int(end["steps"]), "wall_s": round(end["wall_s"], 1),
                    "snapshot_l": "" if math.isnan(l_snap) else round(l_snap, 2),
                    "reversals": "" if math.isnan(rev) else int(rev),
                    "order_length_R": "" if math.isnan(order) else round(order, 2),
                })
    keys = list(rows[0].keys()) if rows else []
    with open(out_runs + ".tmp", "w", newline="") as f:
        w = csv.DictWriter(f, keys)
        w.writeheader()
        w.writerows(rows)
    os.replace(out_runs + ".tmp", out_runs)
    points = {}
    for r in rows:
        points.setdefault((r["variant"], r["mu_s"]), []).append(r)
    with open(out_points + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["variant", "mu_s", "n", "max_D_chord_mean", "max_D_chord_sd",
                    "max_D_chord_sem", "distinct_outcomes", "order_le_0.3l", "reversals_mean",
                    "U_b_hat_end_mean", "steps_mean", "wall_s_mean"])
        for (variant, mu), rs in points.items():
            xs = [r["max_D_chord"] for r in rs]
            sd = statistics.stdev(xs) if len(xs) > 1 else 0.0
            blocks = [r for r in rs if r["order_length_R"] != ""]
            short = (sum(1 for r in blocks if r["order_length_R"] <= 0.3 * r["snapshot_l"])
                     if blocks else "")
            rev = round(statistics.mean(r["reversals"] for r in blocks), 2) if blocks else ""
            w.writerow([variant, mu, len(rs), round(statistics.mean(xs), 4), round(sd, 4),
                        round(sd / math.sqrt(len(xs)), 4), distinct(xs), short,
                        rev,
                        round(statistics.mean(r["U_b_hat_end"] for r in rs), 5),
                        int(statistics.mean(r["steps"] for r in rs)),
                        round(statistics.mean(r["wall_s"] for r in rs), 1)])
    os.replace(out_points + ".tmp", out_points)


if __name__ == "__main__":
    main()
