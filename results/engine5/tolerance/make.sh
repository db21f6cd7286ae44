#!/usr/bin/env bash
# Can the step tolerance be loosened? (docs/measurements.md "Speed of the elastic step", "The
# tolerance cannot be loosened"). rho = 20, xi = 10, eps = 1e3, mu_s = 0 and 0.5, default numerics,
# l = 30, tolerance 1e-3 (default) and 1e-2, seeds 1 and 2 (~40 min on one core); and the fast
# preset to l = 60 at mu_s = 0.5 with tolerance 1e-3, 1e-2 and 0.1 (~10 min). Writes accuracy.csv
# (wirepack accuracy over l in [5, 30]), summary.csv (steps, N, U_b_hat, K at l = 10, 20, 30, 60)
# and, where python3-h5py is installed (scripts/install_paraview.sh installs it), contacts.csv:
# segment pairs at the last snapshot closer than 2 r (1 + gap) for gaps 0 ... 0.2 r.
# Usage: bash results/engine5/tolerance/make.sh [THREADS]
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
here=$root/results/engine5/tolerance
wp=$root/build/wirepack
sweep=$root/sweeps/engine5_tolerance
runs=$root/runs/engine5_tolerance
mkdir -p "$runs"
"$wp" sweep "$here/tolerance.sweep.json" --out "$sweep" --threads "${1:-$(nproc)}" > /dev/null
"$wp" accuracy "$sweep" --window 5,30 --out "$here/acc" --no-plots > /dev/null
mv "$here/acc/accuracy.csv" "$here/accuracy.csv" && rm -rf "$here/acc"
for tol in 0.001 0.01 0.1; do
  echo "{\"rho\": 20, \"xi\": 10, \"eps\": 1000, \"mu_s\": 0.5, \"l_max\": 60,
         \"numerics\": {\"preset\": \"fast\", \"tolerance\": $tol},
         \"output\": {\"snapshots_every_l\": 10}}" > "$runs/fast_tol$tol.json"
  [ -f "$runs/fast_tol$tol.h5" ] || "$wp" run "$runs/fast_tol$tol.json" --out "$runs/fast_tol$tol.h5" > /dev/null
done
echo "run,l,steps,N,U_b_hat,K" > "$here/summary.csv"
for f in "$sweep"/runs/*.h5 "$runs"/fast_tol*.h5; do
  name=$(basename "$f" .h5 | sed 's/_[0-9a-f]\{12\}$//')
  "$wp" export "$f" --csv "$runs/$name.csv" > /dev/null
  awk -F, -v name="$name" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    { l = $c["l"]; for (L = 10; L <= 60; L += 10) if (!(L in done) && l >= L - 1e-9 && l < L + 0.05) {
        done[L] = 1; print name "," L "," $c["steps"] "," $c["N"] "," $c["U_b_hat"] "," $c["K"] } }' \
    "$runs/$name.csv" >> "$here/summary.csv"
done
if /usr/bin/python3 -c "import h5py" 2> /dev/null; then
  /usr/bin/python3 "$here/near_contacts.py" "$sweep"/runs/*.h5 "$runs"/fast_tol*.h5 > "$here/contacts.csv"
fi
column -s, -t "$here/summary.csv"
