#!/usr/bin/env bash
# Where D comes from in Figs. 5a and 5b: per run, the sense blocks at the end of the D window
# (FIG/analysis/morphology.csv: reversals, order length) beside max D_chord over the window
# (FIG/analysis/runs.csv) and the onset of the reversal, read from the run's series: the
# smallest l after which D_chord stays above 0.04 to the end (empty where it never does): above
# what a run with no reversal at the end reaches after l = 20 at mu_s <= 0.2 and eps <= 100
# (0.034, from stretches shorter than R turned back, which the sense blocks merge), and the l at
# which D_chord takes its maximum over the window (the first such row of the series): whether
# the figure's statistic comes from the reversal at the window's end or from an earlier one
# that closed again.
#   bash results/paper/reversals.sh [FIG...]      (default: fig5b fig5a)
# Run `make.sh analyze` first. Writes results/paper/reversals.csv (through a temporary name),
# prints one markdown table per figure and rewrites the README's section between the markers
# "<!-- reversals FIG -->" and "<!-- /reversals FIG -->". With REVERSALS_CSV=PATH it writes PATH
# instead and leaves the README alone, and PAPER_DIR=DIR reads DIR for results/paper (the
# check of tests/golden/check_paper.sh); WIREPACK=PATH names the binary (default build/).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
here=${PAPER_DIR:-$root/results/paper}
wp=${WIREPACK:-$root/build/wirepack}
out=${REVERSALS_CSV:-$here/reversals.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
figs=("$@")
[ ${#figs[@]} -gt 0 ] || figs=(fig5b fig5a)
onset_threshold=0.04

echo "figure,axis,value,seed,file,l,reversals,order_length_R,D_chord_end,D_chord_max,onset_l,l_at_max" \
  > "$tmp/out.csv"
for fig in "${figs[@]}"; do
  an=$here/$fig/analysis
  case $fig in
    fig5b) axis=mu_s ;;
    fig5a) axis=eps ;;
    *) echo "reversals.sh: $fig has no D(x) axis (fig5b or fig5a)" >&2; exit 2 ;;
  esac
  [ -f "$an/morphology.csv" ] && [ -f "$an/runs.csv" ] \
    || { echo "reversals.sh: $an has no morphology.csv or runs.csv (make.sh analyze)" >&2; exit 2; }
  # file -> max D_chord over the window and the window, complete runs only.
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $c["status"] == "complete" { print $c["file"] "," $c["D_chord"] "," $c["D_l_min"] "," $c["D_l_max"] }' \
    "$an/runs.csv" > "$tmp/dmax.csv"
  awk -F, -v axis="$axis" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { print $c["file"], $c[axis], $c["seed"], $c["l"], $c["reversals"], $c["order_length_R"],
            $c["D_chord"] }' "$an/morphology.csv" |
    while read -r file x seed l rev ol dend; do
      read -r dmax wlo whi < <(awk -F, -v f="$file" '$1 == f { print $2, $3, $4; exit }' \
        "$tmp/dmax.csv") || true
      [ -n "${dmax:-}" ] || continue  # morphology of a run that is not complete
      "$wp" export "$here/$fig/sweep/$file" --csv "$tmp/series.csv" > /dev/null
      onset=$(awk -F, -v th="$onset_threshold" '
        NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
        { if ($c["D_chord"] + 0 > th) { if (start == "") start = $c["l"] } else start = "" }
        END { if (start != "") printf "%.1f", start }' "$tmp/series.csv")
      # The analysis takes the max over the rows with l in [D_l_min, D_l_max] (runs.csv).
      lmax=$(awk -F, -v lo="$wlo" -v hi="$whi" '
        NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
        $c["l"] + 0 >= lo + 0 && $c["l"] + 0 <= hi + 0 && (best == "" || $c["D_chord"] + 0 > best) {
          best = $c["D_chord"] + 0; at = $c["l"] }
        END { if (at != "") printf "%.1f", at }' "$tmp/series.csv")
      echo "$fig,$axis,$x,$seed,$file,$l,$rev,$ol,$dend,$dmax,$onset,$lmax"
    done | sort -t, -k3,3g -k4,4n >> "$tmp/out.csv"
done
mv "$tmp/out.csv" "$out.part"
mv "$out.part" "$out"

# One row per value of the axis: seeds, max D_chord (mean, range), reversals per seed,
# order length range, onset range over the runs with a reversal, the l of each seed's max.
table() {
  local fig=$1 label=$2
  echo "| $label | seeds | max D_chord over the window: mean (min–max) | reversals at the window's end, seed by seed | order length / R | onset l (runs that reverse) | l of the max, seed by seed |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  awk -F, -v fig="$fig" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $c["figure"] != fig { next }
    {
      x = $c["value"]
      if (!(x in n)) { order[++nx] = x; lo[x] = 1e9; hi[x] = -1e9; olo[x] = 1e9; ohi[x] = -1e9 }
      n[x]++; sum[x] += $c["D_chord_max"]
      if ($c["D_chord_max"] < lo[x]) lo[x] = $c["D_chord_max"]
      if ($c["D_chord_max"] > hi[x]) hi[x] = $c["D_chord_max"]
      if ($c["order_length_R"] < olo[x]) olo[x] = $c["order_length_R"]
      if ($c["order_length_R"] > ohi[x]) ohi[x] = $c["order_length_R"]
      rev[x] = rev[x] (rev[x] == "" ? "" : " ") $c["reversals"]
      at[x] = at[x] (at[x] == "" ? "" : " ") ($c["l_at_max"] == "" ? "—" : sprintf("%.0f", $c["l_at_max"]))
      if ($c["reversals"] > 0 && $c["onset_l"] != "") {
        o = $c["onset_l"] + 0
        if (!(x in on_lo) || o < on_lo[x]) on_lo[x] = o
        if (!(x in on_hi) || o > on_hi[x]) on_hi[x] = o
      }
    }
    END {
      for (k = 1; k <= nx; ++k) {
        x = order[k]
        onset = (x in on_lo) ? (on_lo[x] == on_hi[x] ? sprintf("%.1f", on_lo[x]) \
                                : sprintf("%.1f–%.1f", on_lo[x], on_hi[x])) : "—"
        printf "| %s | %d | %.3f (%.3f–%.3f) | %s | %.1f–%.1f | %s | %s |\n", x, n[x], sum[x] / n[x],
               lo[x], hi[x], rev[x], olo[x], ohi[x], onset, at[x]
      }
    }' "$out"
}

readme=$here/README.md
[ -z "${REVERSALS_CSV:-}" ] || readme=/dev/null
for fig in "${figs[@]}"; do
  case $fig in
    fig5b) t=$(table fig5b μs) ;;
    fig5a) t=$(table fig5a ε) ;;
  esac
  echo "$fig:"
  echo "$t"
  if [ "$readme" != /dev/null ] && grep -q "<!-- reversals $fig -->" "$readme"; then
    awk -v table="$t" -v first="<!-- reversals $fig -->" -v last="<!-- /reversals $fig -->" '
      $0 == first { print; print table; skip = 1; next }
      $0 == last { skip = 0 }
      !skip' "$readme" > "$readme.part"
    mv "$readme.part" "$readme"
  fi
done
