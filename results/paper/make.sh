#!/usr/bin/env bash
# The paper reproduction campaign (results/paper/README.md). From anywhere, after scripts/setup.sh:
#   bash results/paper/make.sh status [--readme]   runs done and left per figure (partial: runs
#                                                  with a checkpoint to resume from, and the l each
#                                                  has reached; the CPU hours left at the median
#                                                  of its complete runs); runs nothing; with
#                                                  --readme also writes it into the README's
#                                                  section "Status" (checked by
#                                                  tests/golden/check_paper.sh)
#   bash results/paper/make.sh run FIG[,FIG...] [THREADS]
#                                                  runs or resumes the sweeps of the figures given
#                                                  (fig5b, fig5a, fig4, fig1_3) in stages: every
#                                                  point of every one of them gets seeds 1-2 first,
#                                                  then 3-5, then one seed more at a time (6, 7,
#                                                  ...), so that an interrupted campaign still has
#                                                  whole curves with the same seeds at every point
#                                                  (a failed run is kept and listed; the stages go
#                                                  on)
#   bash results/paper/make.sh stop [FIG...]       stops the sweeps running on FIG (all figures by
#                                                  default) with SIGTERM: each run going writes its
#                                                  checkpoint at once; waits until they are gone
#   bash results/paper/make.sh analyze [FIG...]    tables and plots from FIG/sweep into FIG/analysis
#   bash results/paper/make.sh cost [FIG...]       what FIG's complete runs cost: each run file's
#                                                  last wall_s (all sittings of a resumed run) and
#                                                  steps; min, median, mean, max, core-hours, and
#                                                  the figure's wall time on 2 and on 16 cores
#                                                  (core-hours over the cores, at least the
#                                                  longest run); runs nothing
#   bash results/paper/make.sh pictures FIG [last] every snapshot of FIG's runs drawn by wirepack
#                                                  render (ParaView; wire at half its radius,
#                                                  coloured by kappa R) into FIG/pictures; with
#                                                  "last" only each run's last snapshot
# The run data (FIG/sweep: manifest.json, joblog.csv, runs/*.h5) are committed: whoever picks the
# campaign up resumes it. A killed run resumes from its checkpoint (runs/X.h5.ckpt, every 120 s
# of wall time here; commit them too), bitwise as if it had never been interrupted.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
# PAPER_DIR and WIREPACK let tests/golden/check_paper.sh run `status` on a copy of the campaign,
# and PAPER_DIR=results/paper_inertial runs the same campaign under the inertial preset
# (results/paper_inertial/README.md): a folder with the four figures' sweep files.
here=${PAPER_DIR:-$root/results/paper}
wp=${WIREPACK:-$root/build/wirepack}
figs=(fig5b fig5a fig4 fig1_3)

expected_files() {  # FIG -> the run files its sweep file asks for, one per line
  "$wp" validate "$here/$1/$1.sweep.json" | grep -o '"file": "[^"]*"' | cut -d'"' -f4
}

# megabytes DIR [EXCEPT]: the bytes of the files under DIR (but the file EXCEPT) in MB (10^6 B),
# one decimal. File sizes, not disk blocks, so that the figure is the same on every file system
# and in a copy; in a git checkout only the files git keeps or would add (not ignored ones).
megabytes() {
  local files
  if git -C "$1" rev-parse --show-toplevel > /dev/null 2>&1; then
    files=$(cd "$1" && git ls-files -co --exclude-standard .)
  else
    files=$(cd "$1" && find . -type f | sed 's|^\./||')
  fi
  # (A file git tracks may be gone from the tree: a checkpoint whose run has finished.)
  (cd "$1" && grep -vx -- "${2:-}" <<< "$files" | while IFS= read -r f; do
    if [ -f "$f" ]; then stat -c %s "$f"; fi
  done) | awk '{ b += $1 } END { printf "%.1f MB", b / 1e6 }'
}

status() {
  local total_done=0 total=0
  printf '%-7s %5s %5s %6s %8s %11s  %s\n' figure "done" left failed partial "left [CPU h]" \
    "run data"
  for f in "${figs[@]}"; do
    local n=0 done=0 failed=0 partial=0
    while read -r file; do
      n=$((n + 1))
      [ -f "$here/$f/sweep/$file" ] && done=$((done + 1))
      [ -f "$here/$f/sweep/$file.ckpt" ] && partial=$((partial + 1))
    done < <(expected_files "$f")
    if [ -f "$here/$f/sweep/manifest.json" ]; then
      failed=$(grep -c '"status": "failed"' "$here/$f/sweep/manifest.json" || true)
    fi
    local size="-"
    [ -d "$here/$f/sweep" ] && size=$(megabytes "$here/$f/sweep")
    # What is left, at the median wall time of the figure's complete runs (one core each; the
    # joblog's wall_s of a resumed run counts all its sittings); "?" before the first one.
    local cost="?"
    if [ -f "$here/$f/sweep/joblog.csv" ]; then
      cost=$(awk -F, 'NR > 1 && $6 == "complete" { print $5 }' "$here/$f/sweep/joblog.csv" |
        sort -g | awk -v left=$((n - done)) '{ w[++k] = $1 }
          END { if (k == 0) { print "?"; exit }
                m = (k % 2) ? w[(k + 1) / 2] : (w[k / 2] + w[k / 2 + 1]) / 2
                printf "%.1f", left * m / 3600 }')
    fi
    printf '%-7s %5d %5d %6d %8d %11s  %s\n' "$f" "$done" $((n - done)) "$failed" "$partial" \
      "$cost" "$size"
    total_done=$((total_done + done))
    total=$((total + n))
  done
  echo "all: $total_done of $total runs done; results/$(basename "$here") holds" \
    "$(megabytes "$here" README.md) besides its README (budget 150 MB)"
  # How far each partial run is: the last l its checkpoint has recorded (wirepack export of a
  # checkpoint writes the series so far).
  local csv
  csv=$(mktemp)
  for f in "${figs[@]}"; do
    for ckpt in "$here/$f/sweep/runs/"*.h5.ckpt; do
      [ -f "$ckpt" ] || continue
      if "$wp" export "$ckpt" --csv "$csv" > /dev/null 2>&1; then
        echo "partial: $f/sweep/runs/$(basename "$ckpt" .ckpt) at l = $(tail -n 1 "$csv" |
          cut -d, -f1 | awk '{ printf "%.1f", $1 }')"
      else
        echo "partial: $f/sweep/runs/$(basename "$ckpt") cannot be read (the run restarts at l = 0)"
      fi
    done
  done
  rm -f "$csv"
}

run_stage() {  # FIG STAGE THREADS: FIG's sweep with seeds 1-STAGE
  local f=$1 stage=$2 threads=$3
  local sweep=$here/$f/$f.sweep.json seeds
  seeds=$(sweep_seeds "$f")
  sed "s/\"seeds\": $seeds/\"seeds\": $stage/" "$sweep" > "$tmp/$f.sweep.json"
  echo "== $f: seeds 1-$stage ($(date -u +%H:%M:%S) UTC)"
  # Exit 1: every run ended but some failed (kept and listed; `--retry-failed` reruns them):
  # the campaign goes on with the next stage. A stop by signal (128 + N) or bad input (2) ends it.
  local rc=0
  "$wp" sweep "$tmp/$f.sweep.json" --out "$here/$f/sweep" --threads "$threads" \
    --checkpoint-every 120 || rc=$?
  [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || exit "$rc"
}

sweep_seeds() {  # FIG -> the number of seeds its sweep file asks for
  grep -o '"seeds": [0-9]*' "$here/$1/$1.sweep.json" | grep -o '[0-9]*$'
}

run() {  # FIGS THREADS: FIGS one figure or several joined by commas, taken stage by stage
  local threads=$2 f list=()
  IFS=, read -r -a list <<< "$1"
  [ ${#list[@]} -gt 0 ] || { echo "make.sh: no figure given (one of ${figs[*]})" >&2; exit 2; }
  local -A done_to=()
  local most=0 n
  for f in "${list[@]}"; do
    [ -f "$here/$f/$f.sweep.json" ] || { echo "make.sh: no figure $f (one of ${figs[*]})" >&2; exit 2; }
    n=$(sweep_seeds "$f")
    [ "$n" -le "$most" ] || most=$n
    done_to[$f]=0
  done
  tmp=$(mktemp -d)  # the staged sweep files (global: run_stage writes them)
  trap 'rm -rf "$tmp"' EXIT
  # Stages across all the figures given: every figure's seeds 1-2, then 3-5, then one seed
  # more per stage, so that a campaign cut short has the same seeds at every grid point.
  local stage s stages=(2 5)
  for ((s = 6; s <= most; ++s)); do stages+=("$s"); done
  for stage in "${stages[@]}"; do
    for f in "${list[@]}"; do
      s=$stage
      n=$(sweep_seeds "$f")
      [ "$s" -le "$n" ] || s=$n
      [ "$s" -gt "${done_to[$f]}" ] || continue
      run_stage "$f" "$s" "$threads"
      done_to[$f]=$s
    done
    [ "$stage" -lt "$most" ] || break
  done
}

sweep_pids() {  # FIG: the wirepack processes sweeping into FIG/sweep (not their shells)
  local p
  for p in $(pgrep -f -- "--out $here/$1/sweep( |\$)" || true); do
    # The executable, not its name (wirepack re-executes itself as /proc/self/exe).
    case "$(readlink "/proc/$p/exe" 2> /dev/null)" in */wirepack | */wirepack" (deleted)") echo "$p" ;; esac
  done
  return 0
}

stop() {  # FIG: SIGTERM to the sweeps writing into FIG/sweep, then wait for them to exit
  local f=$1 pids
  pids=$(sweep_pids "$f")
  [ -n "$pids" ] || { echo "== $f: no sweep running"; return 0; }
  echo "== $f: stopping $(echo "$pids" | wc -w) sweep(s) (their runs write checkpoints)"
  kill -TERM $pids 2> /dev/null || true
  for _ in $(seq 1 600); do
    [ -n "$(sweep_pids "$f")" ] || { echo "== $f: stopped"; return 0; }
    sleep 0.1
  done
  echo "make.sh: the sweep on $f did not stop within 60 s" >&2
  return 1
}

analyze() {  # FIG
  local f=$1
  [ -d "$here/$f/sweep/runs" ] || { echo "== $f: no run data yet"; return 0; }
  "$wp" analyze "$here/$f/sweep" --out "$here/$f/analysis"
}

cost() {  # FIG: the wall time and steps of its complete runs, from the run files
  local f=$1 csv run
  [ -d "$here/$f/sweep/runs" ] || { echo "== $f: no run data yet"; return 0; }
  csv=$(mktemp)
  for run in "$here/$f"/sweep/runs/*.h5; do
    [ -f "$run" ] || continue
    "$wp" export "$run" --csv "$csv" > /dev/null
    # The last row's wall_s [s] and steps, found by their column names.
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i }
      END { print $col["wall_s"], $col["steps"] }' "$csv"
  done | sort -g | awk -v f="$f" '{ w[++n] = $1; s += $1; st += $2 }
    END {
      if (n == 0) { print "== " f ": no complete run"; exit }
      m = (n % 2) ? w[(n + 1) / 2] : (w[n / 2] + w[n / 2 + 1]) / 2
      h = s / 3600
      t2 = h / 2; if (t2 < w[n] / 3600) t2 = w[n] / 3600
      t16 = h / 16; if (t16 < w[n] / 3600) t16 = w[n] / 3600
      printf "== %s: %d runs, wall per run %.0f-%.0f s, median %.0f s, mean %.0f s, %.0f k steps on average; %.1f core-hours: >= %.1f h on 2 cores, >= %.1f h on 16\n",
        f, n, w[1], w[n], m, s / n, st / n / 1000, h, t2, t16 }'
  rm -f "$csv"
}

pictures() {  # FIG [last]
  local f=$1 which=${2:-all}
  [ -d "$here/$f/sweep/runs" ] || { echo "== $f: no run data yet"; return 0; }
  mkdir -p "$here/$f/pictures"
  for run in "$here/$f"/sweep/runs/*.h5; do
    local name n first=0
    name=$(basename "$run" .h5 | sed 's/_[0-9a-f]\{12\}$//')
    n=$(h5ls "$run/snapshots" | wc -l)
    [ "$which" != last ] || first=$((n - 1))
    for k in $(seq "$first" $((n - 1))); do
      "$wp" render "$run" --snapshot "$k" --half-radius --out "$here/$f/pictures/${name}_k$k.png"
    done
  done
}

# The README's section "Status": what `status` prints, as a code block between the markers
# <!-- status --> and <!-- /status --> (written through a temporary name).
readme_status() {
  local out readme=$here/README.md
  out=$(status)
  printf '%s\n' "$out"
  grep -qx '<!-- status -->' "$readme" ||
    { echo "make.sh: $readme has no <!-- status --> marker" >&2; exit 1; }
  awk -v block="$out" '$0 == "<!-- /status -->" { skip = 0 }
    !skip { print } $0 == "<!-- status -->" { print "```"; print block; print "```"; skip = 1 }' \
    "$readme" > "$readme.tmp"
  mv "$readme.tmp" "$readme"
}

cmd=${1:-status}
case "$cmd" in
  status)
    [ $# -le 2 ] && { [ $# -lt 2 ] || [ "$2" = --readme ]; } ||
      { echo "usage: make.sh status [--readme]" >&2; exit 2; }
    if [ "${2:-}" = --readme ]; then readme_status; else status; fi
    ;;
  run)
    [ $# -ge 2 ] || { echo "usage: make.sh run FIG[,FIG...] [THREADS]" >&2; exit 2; }
    run "$2" "${3:-$(nproc)}"
    ;;
  stop)
    shift
    for f in "${@:-${figs[@]}}"; do stop "$f"; done
    ;;
  analyze)
    shift
    for f in "${@:-${figs[@]}}"; do analyze "$f"; done
    ;;
  cost)
    shift
    for f in "${@:-${figs[@]}}"; do cost "$f"; done
    ;;
  pictures)
    [ $# -ge 2 ] && { [ $# -eq 2 ] || [ "$3" = last ]; } ||
      { echo "usage: make.sh pictures FIG [last]" >&2; exit 2; }
    pictures "$2" "${3:-all}"
    ;;
  *)
    echo "usage: make.sh status [--readme] | run FIG[,FIG...] [THREADS] | stop [FIG...] | analyze [FIG...] | cost [FIG...] | pictures FIG [last]" >&2
    exit 2
    ;;
esac
