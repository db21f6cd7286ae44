#!/usr/bin/env bash
# Installs what wirepack needs from Debian's packages (only what is missing), then configures
# and builds into ./build. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake git pkg-config libeigen3-dev libhdf5-dev nlohmann-json3-dev
          libomp-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev gnuplot-nox hdf5-tools
          clang-format)
scripts/install_packages.sh "${packages[@]}"

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >&2
cmake --build build -j"$(nproc)" >&2
