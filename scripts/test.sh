#!/usr/bin/env bash
# Builds (via setup.sh) and runs the default test suite; long physics runs carry the ctest
# label "slow" and run only with: ctest --test-dir build -L slow
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
ctest --test-dir build -LE slow --output-on-failure -j"$(nproc)" --timeout 600
