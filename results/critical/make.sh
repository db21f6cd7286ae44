#!/usr/bin/env bash
# Reproduces results/critical/: the sharp feature of D(mu_s) at rho = 20, xi = 10, eps = 1e3
# (elastic shell, "fast" preset, l = 20, D = max of D(l) over [5, 20]; at the quasi-static
# numerics every run still coils by l = 20, see the README) with its 95 % bootstrap interval, from a coarse grid (6 mu_s x 4 seeds) refined by
# `wirepack refine` (3 rounds of 2 values x 4 seeds), against a uniform grid of 11 mu_s x 4 seeds
# (its 8 values shared with the refined sweep reuse those run files), and the refined sweep fitted
# on mu_s <= 0.6 only.
# Usage (after scripts/setup.sh): bash results/critical/make.sh [THREADS]
set -euo pipefail
cd "$(dirname "$0")/../.."
threads="${1:-1}"
out=results/critical
coarse=sweeps/critical_mu_l20
uniform=sweeps/critical_mu_l20_uniform

# Copies the tables and the D(mu_s) plot of an analysis of DIR into OUT/NAME.
keep() {
  local dir=$1 name=$2 tmp
  tmp=$(mktemp -d)
  build/wirepack analyze "$dir" --out "$tmp" > /dev/null
  mkdir -p "$out/$name"
  cp "$tmp"/critical.csv "$tmp"/curves.csv "$tmp"/runs.csv "$tmp"/D_vs_mu_s.csv "$out/$name/"
  cp "$tmp"/plots/D_vs_mu_s.png "$out/$name/" 2> /dev/null || true
  rm -rf "$tmp"
}

# 1. The coarse grid, 24 runs.
build/wirepack sweep scenes/critical_mu_l20.sweep.json --out "$coarse" --threads "$threads" \
  > /dev/null
keep "$coarse" coarse
# 2. Refinement: 3 rounds of 8 runs (2 values x 4 seeds) where the interval of mu_c is.
build/wirepack refine "$coarse" --add values --runs 8 --budget 24 --threads "$threads" > /dev/null
keep "$coarse" refined
cp "$coarse"/refine.json "$coarse"/refine_log.csv "$out/refined/"
# 3. The uniform grid with about as many runs (44), reusing the coarse grid's runs.
mkdir -p "$uniform/runs"
build/wirepack validate scenes/critical_mu_l20_uniform.sweep.json |
  sed -n 's/^ *"file": "\(runs\/[^"]*\)",*$/\1/p' | while read -r f; do
  if [ -e "$coarse/$f" ] && [ ! -e "$uniform/$f" ]; then ln "$coarse/$f" "$uniform/$f"; fi
done
build/wirepack sweep scenes/critical_mu_l20_uniform.sweep.json --out "$uniform" \
  --threads "$threads" > /dev/null
keep "$uniform" uniform
# 4. The refined sweep fitted on mu_s <= 0.6 only (D falls again beyond the crumpled maximum).
tmp=$(mktemp -d)
build/wirepack analyze "$coarse" --out "$tmp" --critical-range mu_s=0,0.6 --no-plots > /dev/null
mkdir -p "$out/refined_range"
cp "$tmp"/critical.csv "$out/refined_range/"
rm -rf "$tmp"
