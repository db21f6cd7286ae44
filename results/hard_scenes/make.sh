#!/usr/bin/env bash
# Hard-scene suite (docs/reference.md and docs/measurements.md, "Hard scenes"; issue 19 part 1):
# runs the slow tests sweep.Suite/HardScenes.* one after the other and collects their HARD_SCENE
# lines into results/hard_scenes/runs.csv (one row per scene). Usage, from the repository root
# after a Release build in build/:
#   bash results/hard_scenes/make.sh [BUILD_DIR]
# About 25 min on one core. The test log goes to results/hard_scenes/ctest.log.
set -euo pipefail
build=${1:-build}
out=results/hard_scenes
ctest --test-dir "$build" -L slow -R HardScenes -V -j1 > "$out/ctest.log" 2>&1 || true
{
  echo "name,rho,xi,eps,mu_s,preset,l_max,outcome,l,steps,wall_s,cpu_s,dt_min_s,dt_end_s,ww_overlap_r,wall_overlap_r,shell_overlap_r,E_over_W_end,E_over_W_max,reason"
  grep -o 'HARD_SCENE,.*' "$out/ctest.log" | sed 's/^HARD_SCENE,//'
} > "$out/runs.csv"
grep -E 'tests passed|tests failed' "$out/ctest.log" || true
