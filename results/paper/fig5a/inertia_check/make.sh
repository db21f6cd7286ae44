#!/usr/bin/env bash
# The thin-shell inertia rule at Fig. 5a's xi = 30 (README.md here): mu_s = 1, eps = 10^3 and
# 10^4, seeds 1-2, to l = 12, with the rule (default numerics) and with the former masses
# (numerics.shell_inertia_thickness 0); then table.csv. Runs into DIR (default
# /tmp/wirepack_inertia_check; resumes there).
#   bash results/paper/fig5a/inertia_check/make.sh [DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
wp=$root/build/wirepack
out=${1:-/tmp/wirepack_inertia_check}
for masses in former rule; do
  "$wp" sweep "$here/$masses.sweep.json" --out "$out/$masses" --threads 2
  for f in "$out/$masses"/runs/*.h5; do "$wp" export "$f" --csv "${f%.h5}.csv" > /dev/null; done
done
python3 "$here/table.py" "$out" > "$here/table.csv.tmp"
mv "$here/table.csv.tmp" "$here/table.csv"
echo "table: $here/table.csv"
