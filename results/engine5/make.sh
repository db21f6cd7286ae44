#!/usr/bin/env bash
# Engine V benchmarks (docs/measurements.md "Speed of the elastic step", Engine V tables). Usage,
# from the repository root after scripts/setup.sh, on an otherwise idle 2-core machine:
#   bash results/engine5/make.sh [BEFORE]
# BEFORE: a build directory of an earlier wirepack (e.g. a worktree of the commit before
# Engine V, built with scripts/setup.sh) measured the same way, for the before -> after
# columns. Writes results/engine5/runs.csv (one row per run: label, binary, scene, threads,
# l, steps, wall and CPU seconds, peak memory) and results/engine5/bench_shell_*.txt (the
# shell forces alone and whole elastic steps; after: on 1 and on 2 OpenMP threads).
# Run files go to runs/engine5/ (not committed). About 25 min with BEFORE, 15 without.
set -euo pipefail
out=results/engine5
runs=runs/engine5
mkdir -p "$runs"
before=${1:-}
csv=$out/runs.csv
echo "label,binary,scene,threads,l,steps,wall_s,cpu_s,peak_MiB" > "$csv.part"

scene() {  # name mu l_max numerics
  echo "{\"rho\": 20, \"xi\": 10, \"eps\": 1000, \"mu_s\": $2, \"l_max\": $3,
         \"numerics\": $4, \"output\": {\"snapshots_every_l\": 10}}" > "$runs/$1.json"
}
# One run: label binary_dir scene threads; appends a row.
run() {
  local label=$1 bin=$2 name=$3 threads=$4
  local h5=$runs/$label.h5 log=$runs/$label.time
  local opt=""
  if [ "$threads" != "-" ]; then opt="--threads $threads"; fi
  /usr/bin/time -f "%e %U %M" -o "$log" "$bin/wirepack" run "$runs/$name.json" --out "$h5" $opt \
    2> "$runs/$label.log" > /dev/null
  "$bin/wirepack" export "$h5" --csv "$runs/$label.csv" > /dev/null 2>&1 ||
    build/wirepack export "$h5" --csv "$runs/$label.csv" > /dev/null
  local last; last=$(tail -n 1 "$runs/$label.csv")
  local l steps
  l=$(head -n 1 "$runs/$label.csv" | tr ',' '\n' | grep -n '^l$' | cut -d: -f1)
  steps=$(head -n 1 "$runs/$label.csv" | tr ',' '\n' | grep -n '^steps$' | cut -d: -f1)
  read -r wall cpu mem < "$log"
  echo "$label,$bin,$name,$threads,$(echo "$last" | cut -d, -f"$l"),$(echo "$last" | cut -d, -f"$steps"),$wall,$cpu,$((mem / 1024))" >> "$csv.part"
}

scene ref_mu0 0 30 '"default"'
scene ref_mu0.5 0.5 30 '"default"'
scene long_fast 0.5 60 '"fast"'

# Reference runs to l = 30, the two morphologies side by side (one core each).
for b in ${before:+$before} build; do
  tag=$([ "$b" = build ] && echo after || echo before)
  run "ref_mu0_$tag" "$b" ref_mu0 - & run "ref_mu0.5_$tag" "$b" ref_mu0.5 - & wait
done
# Threads inside one run: a long run (l = 60, fast preset) on 1 and on 2 threads, alone.
run long_fast_1thread build long_fast 1
run long_fast_2threads build long_fast 2
mv "$csv.part" "$csv"

# The whole elastic step and the shell forces alone (ns per face-step), medians of 5.
bench() { "$1/bench_shell" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true; }
for t in 1 2; do OMP_NUM_THREADS=$t bench build > "$out/bench_shell_after_${t}thread.txt" 2>&1; done
if [ -n "$before" ]; then bench "$before" > "$out/bench_shell_before.txt" 2>&1; fi
echo "wrote $csv and $out/bench_shell_*.txt"
