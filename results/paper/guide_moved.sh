#!/usr/bin/env bash
# What the guide moved: every complete run of the campaign that also exists as a pre-guide run
# (the same scene and seed, so the same file name, at commit 920dc9d, the last before the wire
# outside the hole became a contact body), the l where the two first differ
# (first_difference.sh; "none": equal as far as both go; "same file": the pre-guide run file
# itself was kept, so whether the guide changes it is known only from a rerun, listed in
# results/paper/history.md) and the paper's statistics of both: D and D_chord maximised over the
# figure's D window (from each commit's analysis/runs.csv).
#   bash results/paper/guide_moved.sh [FIG...]      (default: fig5b fig5a fig4 fig1_3)
# Writes results/paper/guide_moved.csv (through a temporary name) and prints it. Run
# `make.sh analyze` first: the guide runs' statistics are read from FIG/analysis/runs.csv.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/results/paper
pre=920dc9d
out=$here/guide_moved.csv
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
figs=("$@")
[ ${#figs[@]} -gt 0 ] || figs=(fig5b fig5a fig4 fig1_3)

# FILE (runs.csv) -> "D,D_chord" of that run, from the runs.csv given on stdin
stats() {
  awk -F, -v f="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $c["file"] == f && $c["status"] == "complete" { print $c["D"] "," $c["D_chord"]; exit }'
}

echo "figure,file,seed,first_difference,D_pre_guide,D_guide,D_chord_pre_guide,D_chord_guide" \
  > "$tmp/out.csv"
for f in "${figs[@]}"; do
  now=$here/$f/analysis/runs.csv
  [ -f "$now" ] || continue
  git -C "$root" show "$pre:results/paper/$f/analysis/runs.csv" > "$tmp/pre.csv" 2> /dev/null ||
    continue
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $c["status"] == "complete" { print $c["file"] "," $c["seed"] }' "$now" |
    while IFS=, read -r file seed; do
      after=$(stats "$file" < "$now")
      before=$(stats "$file" < "$tmp/pre.csv")
      [ -n "$before" ] || continue  # no pre-guide run of this scene and seed
      git -C "$root" show "$pre:results/paper/$f/sweep/$file" > "$tmp/pre.h5"
      if cmp -s "$tmp/pre.h5" "$here/$f/sweep/$file"; then
        where="same file"  # the pre-guide run itself, kept: only a rerun can tell
      else
        where=$(bash "$here/first_difference.sh" "$tmp/pre.h5" "$here/$f/sweep/$file")
        case "$where" in
          "first difference at l = "*) where=$(echo "$where" | sed 's/^first difference at l = \([^ ]*\).*/\1/') ;;
          *) where=none ;;
        esac
      fi
      echo "$f,$file,$seed,$where,${before%,*},${after%,*},${before#*,},${after#*,}"
    done >> "$tmp/out.csv"
done
mv "$tmp/out.csv" "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
