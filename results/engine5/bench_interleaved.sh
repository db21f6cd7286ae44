#!/usr/bin/env bash
# bench_shell before -> after, interleaved (docs/measurements.md "Speed of the elastic step",
# bench_shell table): the whole elastic step and the shell forces alone, ns per face-step, medians
# of 5.
# Usage, from the repository root, on an otherwise idle machine:
#   bash results/engine5/bench_interleaved.sh BEFORE [OUT]
# BEFORE: a build directory of the commit before Engine V (ffe83fa) with bench_shell built;
# OUT defaults to results/engine5/bench_$(date +%F). Writes before_{1,2}.txt and
# after1_{1,2}.txt (this build, one OpenMP thread), alternating, then after2_1.txt (2 threads).
# On a machine whose speed drifts, only the interleaved pairs compare. About 15 min.
set -euo pipefail
before=${1:?usage: bench_interleaved.sh BEFORE_BUILD_DIR [OUT]}
out=${2:-results/engine5/bench_$(date +%F)}
mkdir -p "$out"
bench() { "$1/bench_shell" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true; }
for round in 1 2; do
  OMP_NUM_THREADS=1 bench "$before" > "$out/before_$round.txt" 2>&1
  OMP_NUM_THREADS=1 bench build > "$out/after1_$round.txt" 2>&1
done
OMP_NUM_THREADS=2 bench build > "$out/after2_1.txt" 2>&1
echo "wrote $out/{before,after1,after2}_*.txt"
