#!/usr/bin/env bash
# The crumpling study (results/crumpling/README.md): Fig. 5b's scene (rho = 20, xi = 10,
# eps = 1e3) with one candidate cause changed per sweep file, each run like the paper's runs.
#   bash results/crumpling/make.sh run NAME [NAME ...]   runs (or resumes) SET/NAME.sweep.json
#                                                        (NAME as SET/NAME, e.g. screen/absolute)
#                                                        into runs/SET/NAME, two runs at a time,
#                                                        one core each
#   bash results/crumpling/make.sh summary               runs.csv and points.csv of every sweep
#                                                        directory under runs/ (summary.py)
#   bash results/crumpling/make.sh twin NAME             the twin pair of twin/NAME.sweep.json:
#                                                        where its two runs part (wirepack twin)
# The run files stay in runs/ (not committed); the summaries are.
set -euo pipefail
export LC_ALL=C
here=$(cd "$(dirname "$0")" && pwd)
wp=${WIREPACK:-$here/../../build/wirepack}
cmd=${1:-}
shift || true
case $cmd in
  run)
    for name in "$@"; do
      [ -f "$here/$name.sweep.json" ] || { echo "make.sh: no $here/$name.sweep.json" >&2; exit 2; }
      mkdir -p "$here/runs/$(dirname "$name")"
      echo "$(date -u +%FT%TZ) $name"
      OMP_NUM_THREADS=1 "$wp" sweep "$here/$name.sweep.json" --out "$here/runs/$name" \
        --threads 2 --checkpoint-every 120 > "$here/runs/$name.log" 2>&1 || true
      tail -1 "$here/runs/$name.log"
    done
    ;;
  summary)
    args=()
    for d in "$here"/runs/*/*/; do
      [ -f "$d/manifest.json" ] || continue
      rel=${d#"$here"/runs/}
      args+=("${rel%/}=$d")
    done
    python3 "$here/summary.py" "$wp" "$here/runs.csv" "$here/points.csv" "${args[@]}"
    column -s, -t "$here/points.csv"
    ;;
  twin)
    name=${1:?twin NAME}
    runs=("$here/runs/twin/$name"/runs/*.h5)
    [ ${#runs[@]} = 2 ] || { echo "make.sh: twin $name has ${#runs[@]} run files, not 2" >&2; exit 1; }
    "$wp" twin "${runs[0]}" "${runs[1]}" --csv "$here/twin_$name.csv"
    ;;
  *)
    sed -n '2,13p' "$0"
    exit 2
    ;;
esac
