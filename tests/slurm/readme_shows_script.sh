#!/usr/bin/env bash
# docs/reference.md's job-array script (the bash block of section "Shards and SLURM job arrays") is
# exactly scripts/slurm_sweep.sbatch, the file tests/slurm/test_slurm.sh runs on a real SLURM.
#   tests/slurm/readme_shows_script.sh docs/reference.md scripts/slurm_sweep.sbatch
set -euo pipefail
readme=$1
script=$2
block=$(awk '/^### Shards and SLURM job arrays$/ { in_section = 1; next }
             in_section && /^### / { exit }
             in_section && !in_block && /^```bash$/ { in_block = 1; next }
             in_block && /^```$/ { exit }
             in_block { print }' "$readme")
if [ -z "$block" ]; then
  echo "$readme: no bash block in section \"Shards and SLURM job arrays\"" >&2
  exit 1
fi
if ! diff -u <(printf '%s\n' "$block") "$script"; then
  echo "$readme: the job-array script of section \"Shards and SLURM job arrays\" differs from" \
    "$script (above: $readme, then the file); copy the file into $readme" >&2
  exit 1
fi
echo "$readme shows $script exactly"
