#!/usr/bin/env python3
"""Table of the inertia check (README.md): the series of every run at l = 4, 6, 8, 10, 12.

  python3 table.py DIR > table.csv     DIR holds former/runs/*.csv and rule/runs/*.csv
(`wirepack export RUN.h5 --csv RUN.csv` of each run file, as make.sh does)."""
import csv
import glob
import os
import sys

COLUMNS = ["U_b_hat", "K", "D", "D_chord", "N", "U_m", "U_sb", "steps"]


def main(root):
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["masses", "eps", "seed", "l"] + COLUMNS)
    for masses in ("former", "rule"):
        for path in sorted(glob.glob(os.path.join(root, masses, "runs", "*.csv"))):
            name = os.path.basename(path)  # eps-1000_s1_<id>.csv
            eps = name.split("_")[0].split("-", 1)[1]
            seed = name.split("_")[1].lstrip("s")
            rows = list(csv.DictReader(open(path)))
            for l in (4, 6, 8, 10, 12):
                r = min(rows, key=lambda r: abs(float(r["l"]) - l))
                out.writerow([masses, eps, seed, l] + ["%.4g" % float(r[c]) for c in COLUMNS])


if __name__ == "__main__":
    main(sys.argv[1])
