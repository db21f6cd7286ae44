#!/usr/bin/env bash
# Optional: installs SLURM (slurmctld, slurmd, the client commands) and MUNGE from Debian's
# packages, only what is missing, for the job-array test (ctest --test-dir build -L slurm,
# tests/slurm/test_slurm.sh). Not part of setup.sh: wirepack itself needs no SLURM.
# The test starts its own one-node cluster in a temporary directory (its own slurm.conf, munge
# key and socket, free ports); the system services the packages bring are neither configured
# nor started here.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_packages.sh slurm-wlm munge
for cmd in slurmctld slurmd munged sbatch sinfo squeue scancel; do
  if ! command -v "$cmd" >/dev/null; then
    echo "install_slurm: $cmd not found after the install" >&2
    exit 1
  fi
done
echo "install_slurm: $(slurmctld -V), $(munged --version 2>&1 | head -n1)" >&2
