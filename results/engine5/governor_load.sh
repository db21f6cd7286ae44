#!/usr/bin/env bash
# A load that arrives while a run holds 2 threads (docs/measurements.md "Speed of the elastic step",
# "Fewer threads when more are slower"). Runs `wirepack run --threads THREADS` of the elastic
# reference scene at mu_s 0.5 (rho 20, xi 10, eps 1e3, default numerics) alone for 30 s, then beside
# a busy loop at equal priority (its own session, so its own scheduler group) for 120 s, and prints
# the l the run had reached at 30 s and at the end. Usage, from the repository root:
#   bash results/engine5/governor_load.sh [WIREPACK] [THREADS]   (defaults build/wirepack, 2)
# Compare two binaries (or 2 threads against 1) one after the other in one sitting: the l gained
# beside the loop is the figure; the run file is deleted.
set -euo pipefail
wp=${1:-build/wirepack}
threads=${2:-2}
tmp=$(mktemp -d)
trap 'kill "${run:-}" "${busy:-}" 2> /dev/null || true; rm -rf "$tmp"' EXIT
echo '{"rho": 20, "xi": 10, "eps": 1000, "mu_s": 0.5, "shell": "elastic", "l_max": 40,
       "seed": 1, "numerics": "default"}' > "$tmp/scene.json"
# The progress line ("l = X / 40  wall ...") is rewritten in place on stderr.
last_l() { tr '\r' '\n' < "$tmp/err" | grep -o '^l = [0-9.]*' | tail -n 1 | cut -d' ' -f3; }
setsid "$wp" run "$tmp/scene.json" -o "$tmp/run.h5" --threads "$threads" \
  --checkpoint-every 0 > /dev/null 2> "$tmp/err" &
run=$!
sleep 30
l_alone=$(last_l)
setsid bash -c 'while :; do :; done' &
busy=$!
sleep 120
l_end=$(last_l)
echo "$wp, $threads thread(s): l = $l_alone after 30 s alone, l = $l_end after 120 s more beside a busy loop"
