#!/usr/bin/env bash
# The accuracy-vs-time study (docs/reference.md and docs/measurements.md, "Accuracy and presets"):
# runs the one-knob ladders of scenes/accuracy/*.sweep.json (rigid: rho = 20, mu_s = 0, l = 20;
# elastic: rho = 20, xi = 10, eps = 1e3, mu_s = 0 and 0.5, l = 8) and the presets into
# sweeps/accuracy/NAME, then `wirepack accuracy` over the ladders into OUT (default
# results/accuracy) and over the presets into OUT/presets. Resumable: rerun it and finished runs are
# kept.
# Usage: scripts/accuracy_study.sh [rigid|elastic|all] [THREADS] [OUT]
set -euo pipefail
cd "$(dirname "$0")/.."
which=${1:-all}
threads=${2:-$(nproc)}
out=${3:-results/accuracy}
case $which in rigid | elastic | all) ;; *) echo "usage: $0 [rigid|elastic|all] [THREADS] [OUT]" >&2; exit 2 ;; esac
[ -x build/wirepack ] || scripts/setup.sh
ladders=() presets=()
for f in scenes/accuracy/*.sweep.json; do
  name=$(basename "$f" .sweep.json)
  [ "$which" = all ] || [[ $name == "$which"_* ]] || continue
  build/wirepack sweep "$f" --out "sweeps/accuracy/$name" --threads "$threads" > /dev/null
  if [[ $name == *_preset ]]; then presets+=("sweeps/accuracy/$name"); else ladders+=("sweeps/accuracy/$name"); fi
done
# The one-knob ladders and the seed floor; then the presets, each against the finest preset.
build/wirepack accuracy "${ladders[@]}" --out "$out"
build/wirepack accuracy "${presets[@]}" --out "$out/presets"
