#!/usr/bin/env bash
# Builds every target with -fsanitize=address,undefined into build-asan (RelWithDebInfo at -O1
# with line tables: the optimisation ASan recommends, and half the compile time of -O2 -g; no
# benchmarks) and runs the fast suite (ctest -LE slow) under it: any ASan, LeakSanitizer or
# UBSan report makes a test fail (halt_on_error). Needs what scripts/setup.sh installs.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DWIREPACK_BENCH=OFF -DWIREPACK_SANITIZE=address,undefined >&2
cmake --build build-asan -j"$(nproc)" >&2
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export ASAN_OPTIONS=detect_leaks=1
ctest --test-dir build-asan -LE slow --output-on-failure -j"$(nproc)" --timeout 1800
