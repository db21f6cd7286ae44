#!/usr/bin/env bash
# Engine V, second round (docs/measurements.md "Speed of the elastic step"): the elastic reference
# runs on one thread, and a long run on 1 and on 2 threads. Usage, from the repository root after
# scripts/setup.sh, on an otherwise idle 2-core machine:
#   bash results/engine5/make_threads.sh [refs|threads|all]   (default all)
# refs: the two reference runs (rho 20, xi 10, eps 1e3, default numerics, to l = 30), one after
# the other on one thread (~3 + 5 min). threads: the fast preset, mu_s 0.5, to l = 60, on 1 and
# then on 2 threads (~4 + 3 min). Appends one row per run to results/engine5/threads.csv (label,
# threads, l, steps, wall and CPU seconds, peak memory, date); run files go to runs/engine5/.
set -euo pipefail
out=results/engine5
runs=runs/engine5
mkdir -p "$runs"
what=${1:-all}
csv=$out/threads.csv
[ -f "$csv" ] || echo "label,threads,l,steps,wall_s,cpu_s,peak_MiB,date" > "$csv"

scene() {  # name mu l_max numerics
  echo "{\"rho\": 20, \"xi\": 10, \"eps\": 1000, \"mu_s\": $2, \"l_max\": $3,
         \"numerics\": $4, \"output\": {\"snapshots_every_l\": 10}}" > "$runs/$1.json"
}
# One run of build/wirepack with N threads; appends a row. wirepack sets GOMP_SPINCOUNT itself
# (app/main.cpp) unless the environment has a wait policy: clear one inherited from ctest.
run() {  # label scene threads
  local label=$1 name=$2 threads=$3
  local h5=$runs/$label.h5 log=$runs/$label.time
  env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT /usr/bin/time -f "%e %U %S %M" -o "$log" \
    build/wirepack run "$runs/$name.json" --out "$h5" --threads "$threads" \
    2> "$runs/$label.log" > /dev/null
  build/wirepack export "$h5" --csv "$runs/$label.csv" > /dev/null
  local head last col_l col_steps
  head=$(head -n 1 "$runs/$label.csv")
  last=$(tail -n 1 "$runs/$label.csv")
  col_l=$(echo "$head" | tr ',' '\n' | grep -n '^l$' | cut -d: -f1)
  col_steps=$(echo "$head" | tr ',' '\n' | grep -n '^steps$' | cut -d: -f1)
  read -r wall user sys mem < "$log"
  echo "$label,$threads,$(echo "$last" | cut -d, -f"$col_l"),$(echo "$last" | cut -d, -f"$col_steps"),$wall,$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }'),$((mem / 1024)),$(date -u +%F)" >> "$csv"
  tail -n 1 "$csv"
}

scene ref_mu0 0 30 '"default"'
scene ref_mu0.5 0.5 30 '"default"'
scene long_fast 0.5 60 '"fast"'
if [ "$what" = refs ] || [ "$what" = all ]; then
  run ref_mu0_1thread ref_mu0 1
  run ref_mu0.5_1thread ref_mu0.5 1
fi
if [ "$what" = threads ] || [ "$what" = all ]; then
  run long_fast_1thread long_fast 1
  run long_fast_2threads long_fast 2
fi
echo "wrote $csv"
