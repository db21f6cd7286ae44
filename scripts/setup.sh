#!/usr/bin/env bash
# Installs what wirepack needs from Debian's packages (only what is missing), then configures
# and builds into ./build. Safe to run again.
#   scripts/setup.sh [--with-paraview]
# --with-paraview also installs ParaView, xvfb and ffmpeg for `wirepack render`
# (scripts/install_paraview.sh, several hundred MB); without it `wirepack render` falls back
# to gnuplot.
set -euo pipefail
cd "$(dirname "$0")/.."
with_paraview=0
for arg in "$@"; do
  case $arg in
    --with-paraview) with_paraview=1 ;;
    *)
      echo "usage: scripts/setup.sh [--with-paraview]" >&2
      exit 2
      ;;
  esac
done

packages=(build-essential cmake git pkg-config libeigen3-dev libhdf5-dev nlohmann-json3-dev
          libomp-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev gnuplot-nox hdf5-tools
          clang-format time)
scripts/install_packages.sh "${packages[@]}"
if [ "$with_paraview" = 1 ]; then scripts/install_paraview.sh; fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >&2
cmake --build build -j"$(nproc)" >&2
