#!/usr/bin/env bash
# Where two runs of one scene part: the first recorded l at which any series of A differs from
# B's, value for value as the run files store them (wirepack export writes every double so that
# it reads back exactly, so equal text is equal bits). wall_s, the wall time, is left out. A or B
# may be a checkpoint (RUN.h5.ckpt) of a run part-way: then only what both have recorded counts;
# or the CSV `wirepack export --csv` wrote of one (a name ending in .csv).
#   bash results/paper/first_difference.sh A.h5 B.h5
# Prints one line: "equal to l = X (A ends at l = ..., B at l = ...)" when every common row is
# equal, else "first difference at l = Y (equal to l = X; columns C1 C2 ...)". Exit 0 in both
# cases, 2 when a file cannot be read or the two do not record the same series.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: first_difference.sh A.h5 B.h5" >&2; exit 2; }
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
# Row by row over the rows both have; the first row whose cells differ (wall_s apart) ends it.
paste -d '\n' "$tmp/1.csv" "$tmp/2.csv" > "$tmp/rows"
awk -F, -v a_end="$(tail -n 1 "$tmp/1.csv" | cut -d, -f1)" \
  -v b_end="$(tail -n 1 "$tmp/2.csv" | cut -d, -f1)" '
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
