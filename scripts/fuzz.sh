#!/usr/bin/env bash
# Builds the libFuzzer target over the scene and sweep parsers (tests/fuzz/fuzz_config.cpp) with
# clang, ASan and UBSan into build-fuzz, and runs it from the committed corpus
# (tests/fuzz/corpus, left unchanged: new inputs go to build-fuzz/corpus).
#   scripts/fuzz.sh            20000 inputs (what CI runs, about a minute)
#   scripts/fuzz.sh 1000000    longer; or FUZZ_ARGS="-max_total_time=3600" scripts/fuzz.sh 0
# A crash, an uncaught exception, a sanitizer report or a message that does not name the file
# stops it with the input saved as build-fuzz/crash-*; replay one with
# build-fuzz/fuzz_config build-fuzz/crash-<hash>.
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-20000}"
# clang and its runtimes (libFuzzer, ASan, UBSan: libclang-rt-dev, only a recommendation of clang).
scripts/install_packages.sh clang libclang-rt-dev
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DWIREPACK_TESTS=OFF -DWIREPACK_BENCH=OFF -DWIREPACK_FUZZ=ON \
  -DWIREPACK_SANITIZE=address,undefined,fuzzer-no-link >&2
cmake --build build-fuzz --target fuzz_config -j"$(nproc)" >&2
mkdir -p build-fuzz/corpus
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export ASAN_OPTIONS=detect_leaks=1
# shellcheck disable=SC2086
build-fuzz/fuzz_config -runs="$runs" -seed=19 -max_len=4096 -timeout=60 \
  -artifact_prefix=build-fuzz/ ${FUZZ_ARGS:-} build-fuzz/corpus tests/fuzz/corpus
