#!/usr/bin/env bash
# Optional: installs ParaView's batch renderer (pvbatch, its Python bindings, h5py to read run
# files), an X server for off-screen rendering (xvfb-run) and ffmpeg from Debian's packages,
# only what is missing, for `wirepack render` (scripts/render_paraview.py) and its tests
# (ctest --test-dir build -L paraview). Not part of the default setup (several hundred MB):
# `scripts/setup.sh --with-paraview` runs it.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_packages.sh paraview python3-paraview python3-h5py xvfb xauth ffmpeg
for cmd in pvbatch xvfb-run ffmpeg ffprobe; do
  if ! command -v "$cmd" >/dev/null; then
    echo "install_paraview: $cmd not found after the install" >&2
    exit 1
  fi
done
echo "install_paraview: $(pvbatch --version 2>/dev/null | head -n1 || echo pvbatch), $(ffmpeg -version | head -n1)" >&2
