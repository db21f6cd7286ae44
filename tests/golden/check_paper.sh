#!/usr/bin/env bash
# The paper reproduction's committed tables are what `wirepack analyze` makes from its committed
# run data (issue 15): for every figure of results/paper with run files and an analysis folder,
# the analysis is rerun into a temporary folder and every CSV compared byte for byte with the
# committed one, and so are a figure's tables along l (along_l.sh, rerun) and the sense blocks
# of Figs. 5a and 5b (results/paper/reversals.csv, reversals.sh rerun), and the README's
# generated sections are what their scripts make of those tables (table.sh: the comparison table
# and Fig. 5's curves; reversals.sh: the sense-block tables; make.sh status: the status). Exit 77
# (skipped) while no figure has both yet.
# In a git checkout where results/paper differs from HEAD only in run data (FIG/sweep/...: a
# campaign going on beside the tests, its tables not remade yet), HEAD's tables and run data are
# checked (git archive), so the test does not fail on a working tree the campaign has moved on;
# any other change to results/paper (remade tables, scripts) is checked as it stands.
# Usage: check_paper.sh WIREPACK SOURCE_DIR
set -euo pipefail
wirepack=$1
paper=$2/results/paper
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
top=$(git -C "$2" rev-parse --show-toplevel 2> /dev/null || true)
if [ -n "$top" ] && [ "$(cd "$top" && pwd -P)" = "$(cd "$2" && pwd -P)" ] &&
  git -C "$2" rev-parse --verify -q HEAD > /dev/null; then
  changed=$( (git -C "$2" diff --no-renames --name-only HEAD -- results/paper &&
    git -C "$2" ls-files --others --exclude-standard -- results/paper) | sort -u)
  if [ -n "$changed" ] && ! grep -qv '^results/paper/[^/]*/sweep/' <<< "$changed"; then
    echo "results/paper differs from HEAD only in run data (a campaign going on): checking HEAD's"
    mkdir "$tmp/head"
    git -C "$2" archive HEAD results/paper | tar -x -C "$tmp/head"
    paper=$tmp/head/results/paper
  fi
fi
# same COMMITTED MADE FIG REMAKE: every CSV of the folder COMMITTED (results/paper/FIG/...) is
# byte for byte the one in MADE, or the difference is shown with the command REMAKE.
same() {
  local csv
  for csv in "$1"/*.csv; do
    if ! diff -q "$csv" "$2/$(basename "$csv")" >/dev/null; then
      { diff "$csv" "$2/$(basename "$csv")" || true; } | head -20
      echo "results/paper/$3/$(basename "$1")/$(basename "$csv") is not what the run data in" \
        "results/paper/$3/sweep make: rerun $4"
      exit 1
    fi
  done
}
# run LOG COMMAND...: COMMAND with its output in LOG, shown if it fails.
run() {
  local log=$1
  shift
  "$@" >/dev/null 2>"$log" || { cat "$log"; exit 1; }
}
checked=0
for dir in "$paper"/*/; do
  fig=$(basename "$dir")
  compgen -G "$dir/sweep/runs/*.h5" >/dev/null || continue
  [ -d "$dir/analysis" ] || continue
  # What the analysis reads: the manifest, the joblog and the finished run files (each renamed
  # into place whole). Not the checkpoints and temporary files of runs going on beside the test:
  # they are rewritten and renamed every 2 min, and a copy of the whole folder can meet one
  # half-renamed.
  mkdir -p "$tmp/$fig/runs"
  cp "$dir/sweep/manifest.json" "$tmp/$fig/"
  [ ! -f "$dir/sweep/joblog.csv" ] || cp "$dir/sweep/joblog.csv" "$tmp/$fig/"
  cp "$dir"/sweep/runs/*.h5 "$tmp/$fig/runs/"
  run "$tmp/$fig.log" "$wirepack" analyze "$tmp/$fig" --out "$tmp/$fig.out" --no-plots
  same "$dir/analysis" "$tmp/$fig.out" "$fig" "bash results/paper/make.sh analyze $fig"
  # A figure's tables along l (fig4/along_l.sh), remade the same way.
  if [ -f "$dir/along_l.sh" ] && [ -d "$dir/along_l" ]; then
    run "$tmp/$fig.along.log" bash "$dir/along_l.sh" "$wirepack" "$tmp/$fig.along_l"
    same "$dir/along_l" "$tmp/$fig.along_l" "$fig" "bash results/paper/$fig/along_l.sh"
  fi
  checked=$((checked + 1))
  echo "results/paper/$fig: analysis tables match the run data"
done
# section FILE FIRST LAST: the lines of FILE strictly between the lines FIRST and LAST.
section() {
  awk -v first="$2" -v last="$3" '$0 == last { on = 0 } on; $0 == first { on = 1 }' "$1"
}
# The sense blocks and reversal onsets per run (reversals.sh), remade from the same run data;
# the tables it prints are the README's sections between its markers.
if [ -f "$paper/reversals.csv" ]; then
  env WIREPACK="$wirepack" PAPER_DIR="$paper" REVERSALS_CSV="$tmp/reversals.csv" \
    bash "$2/results/paper/reversals.sh" > "$tmp/reversals.out" 2> "$tmp/reversals.log" ||
    { cat "$tmp/reversals.log"; exit 1; }
  if ! diff -q "$paper/reversals.csv" "$tmp/reversals.csv" > /dev/null; then
    { diff "$paper/reversals.csv" "$tmp/reversals.csv" || true; } | head -20
    echo "results/paper/reversals.csv is not what the run data make: rerun" \
      "bash results/paper/reversals.sh"
    exit 1
  fi
  for fig in fig5b fig5a; do
    grep -qx "<!-- reversals $fig -->" "$paper/README.md" || continue
    awk -v head="$fig:" '$0 == head { on = 1; next } /^fig[0-9a-z_]*:$/ { on = 0 } on' \
      "$tmp/reversals.out" > "$tmp/reversals.$fig.md"
    if ! section "$paper/README.md" "<!-- reversals $fig -->" "<!-- /reversals $fig -->" |
      diff - "$tmp/reversals.$fig.md" > "$tmp/reversals.$fig.diff"; then
      head -20 "$tmp/reversals.$fig.diff"
      echo "results/paper/README.md: the sense-block table of $fig is not what the run data" \
        "make: rerun bash results/paper/reversals.sh"
      exit 1
    fi
  done
  echo "results/paper/reversals.csv and the README's sense-block tables match the run data"
fi
# The README's comparison table and Fig. 5's curves (table.sh), remade from the analysis tables
# on a copy of the README.
if grep -qx "<!-- table -->" "$paper/README.md"; then
  mkdir "$tmp/table"
  cp "$paper/README.md" "$2/results/paper/table.sh" "$tmp/table/"
  for dir in "$paper"/*/analysis; do
    mkdir -p "$tmp/table/$(basename "$(dirname "$dir")")"
    cp -r "$dir" "$tmp/table/$(basename "$(dirname "$dir")")/"
  done
  run "$tmp/table.log" bash "$tmp/table/table.sh"
  if ! diff "$paper/README.md" "$tmp/table/README.md" > "$tmp/table.diff"; then
    head -20 "$tmp/table.diff"
    echo "results/paper/README.md: the comparison table or Fig. 5's curves are not what the" \
      "analysis tables make: rerun bash results/paper/table.sh"
    exit 1
  fi
  echo "results/paper/README.md: the comparison table and Fig. 5's curves match the tables"
fi
# The README's section "Status": what `make.sh status` prints of the same run data.
if grep -qx "<!-- status -->" "$paper/README.md"; then
  env WIREPACK="$wirepack" PAPER_DIR="$paper" bash "$2/results/paper/make.sh" status \
    > "$tmp/status.out" 2> "$tmp/status.log" || { cat "$tmp/status.log"; exit 1; }
  { echo '```'; cat "$tmp/status.out"; echo '```'; } > "$tmp/status.md"
  if ! section "$paper/README.md" "<!-- status -->" "<!-- /status -->" |
    diff - "$tmp/status.md" > "$tmp/status.diff"; then
    head -20 "$tmp/status.diff"
    echo "results/paper/README.md: the section \"Status\" is not what the run data give: rerun" \
      "bash results/paper/make.sh status --readme"
    exit 1
  fi
  echo "results/paper/README.md: the status matches the run data"
fi
if [ "$checked" = 0 ]; then
  echo "no figure of results/paper has run data and tables yet"
  exit 77
fi
