#!/usr/bin/env bash
# Reproduces results/elastic_mu_curve_l20/: a short version of the paper's Fig. 5b, D(mu_s) on
# the elastic shell (rho = 20, xi = 10, eps = 1e3, default numerics): six mu_s x 2 seeds to
# l = 20, D maximised over l in [5, 20]. ~28 min of CPU, ~16 min on the 2-core machine. The full
# curve (10 seeds to l = 50, a night or a cluster job) is scenes/elastic_mu_curve.sweep.json.
# Usage (after scripts/setup.sh): bash results/elastic_mu_curve_l20/make.sh [THREADS]
set -euo pipefail
cd "$(dirname "$0")/../.."
build/wirepack sweep scenes/elastic_mu_curve_l20.sweep.json --out sweeps/elastic_mu_curve_l20 \
  --threads "${1:-$(nproc)}" > /dev/null
build/wirepack analyze sweeps/elastic_mu_curve_l20 --out results/elastic_mu_curve_l20
