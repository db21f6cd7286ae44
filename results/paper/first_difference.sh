#!/usr/bin/env bash
# Where two runs of one scene part: the first recorded l at which any series of A differs from
# B's, value for value as the run files store them (wirepack export writes every double so that
# it reads back exactly, so equal text is equal bits). wall_s, the wall time, is left out. A or B
# may be a checkpoint (RUN.h5.ckpt) of a run part-way: then only what both have recorded counts;
# or the CSV `wirepack export --csv` wrote of one (a name ending in .csv).
#   bash results/paper/first_difference.sh [--steps] A.h5 B.h5
# Prints one line: "equal to l = X (A ends at l = ..., B at l = ...)" when every common row is
# equal, else "first difference at l = Y (equal to l = X; columns C1 C2 ...)". Exit 0 in both
# cases, 2 when a file cannot be read or the two do not record the same series.
# --steps: for runs recorded at other intervals of l (e.g. Fig. 4's 0.25 l against Fig. 5b's
# 0.1 l: the same scene to l = 50), compare the rows recorded at the same step count instead:
# "equal at N common steps, to l = X (...)" or "first difference at step S, l = Y (...)".
set -euo pipefail
by_steps=0
if [ "${1:-}" = --steps ]; then
  by_steps=1
  shift
fi
[ $# -eq 2 ] || { echo "usage: first_difference.sh [--steps] A.h5 B.h5" >&2; exit 2; }
root=$(cd "$(dirname "$0")/../.." && pwd)
wp=${WIREPACK:-$root/build/wirepack}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for k in 1 2; do
  case "${!k}" in
    *.csv) cp "${!k}" "$tmp/$k.csv" 2> /dev/null ;;
    *) "$wp" export "${!k}" --csv "$tmp/$k.csv" > /dev/null ;;
  esac || { echo "first_difference.sh: cannot read ${!k}" >&2; exit 2; }
done
if [ "$(head -n 1 "$tmp/1.csv")" != "$(head -n 1 "$tmp/2.csv")" ]; then
  echo "first_difference.sh: $1 and $2 record different series" >&2
  exit 2
fi
a_end=$(tail -n 1 "$tmp/1.csv" | cut -d, -f1)
b_end=$(tail -n 1 "$tmp/2.csv" | cut -d, -f1)
if [ "$by_steps" = 1 ]; then
  # Rows of B in order, each compared with A's row of the same step count, where A has one.
  awk -F, -v a_end="$a_end" -v b_end="$b_end" '
    FNR == 1 { for (i = 1; i <= NF; ++i) { name[i] = $i; if ($i == "steps") col = i }; next }
    !col { print "first_difference.sh: no steps column" > "/dev/stderr"; bad = 1; exit 2 }
    NR == FNR { row[$col] = $0; next }
    ($col in row) {
      split(row[$col], a, ",")
      diff = ""
      for (i = 1; i <= NF; ++i)
        if (name[i] != "wall_s" && ($i "") != (a[i] "")) diff = diff " " name[i]
      if (diff != "") {
        printf "first difference at step %s, l = %.6g (equal at %d earlier common steps; columns%s)\n",
          $col, $1, n, diff
        found = 1
        exit
      }
      ++n
      last = sprintf("%.6g", $1)
    }
    END {
      if (bad) exit 2
      if (!found && n == 0) printf "no common steps (A ends at l = %s, B at l = %s)\n", a_end, b_end
      else if (!found)
        printf "equal at %d common steps, to l = %s (A ends at l = %.6g, B at l = %.6g)\n", n, last,
          a_end, b_end
    }' "$tmp/1.csv" "$tmp/2.csv"
  exit
fi
# Row by row over the rows both have; the first row whose cells differ (wall_s apart) ends it.
paste -d '\n' "$tmp/1.csv" "$tmp/2.csv" > "$tmp/rows"
awk -F, -v a_end="$a_end" -v b_end="$b_end" '
  NR == 1 { for (i = 1; i <= NF; ++i) name[i] = $i; next }
  NR == 2 { next }
  $0 == "" { exit }  # past the end of the shorter series
  NR % 2 == 1 { split($0, a, ","); next }
  {
    diff = ""
    for (i = 1; i <= NF; ++i)
      if (name[i] != "wall_s" && ($i "") != (a[i] "")) diff = diff " " name[i]
    if (diff != "") {
      printf "first difference at l = %.6g (%s; columns%s)\n", a[1],
        last == "" ? "the first row" : "equal to l = " last, diff
      found = 1
      exit
    }
    last = sprintf("%.6g", a[1])
  }
  END {
    if (!found && last == "")
      printf "no common rows (A ends at l = %s, B at l = %s)\n", a_end, b_end
    else if (!found)
      printf "equal to l = %s (A ends at l = %.6g, B at l = %.6g)\n", last, a_end, b_end
  }' "$tmp/rows"
