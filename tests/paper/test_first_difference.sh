#!/usr/bin/env bash
# results/paper/first_difference.sh, which the campaign uses to say where a rerun departs from a
# committed run: synthetic series with known answers (a difference in one cell of one row, in
# wall_s only, NaN cells, series of different lengths, different columns), then two real runs of
# one rigid scene to l = 3 and l = 4 (equal to l = 3) and two that differ from their first row.
# Usage: test_first_difference.sh WIREPACK SOURCE_DIR
set -euo pipefail
export WIREPACK=$1
fd=$2/results/paper/first_difference.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
expect() {  # EXPECTED A B: the script's line for A and B is EXPECTED
  local got
  got=$(bash "$fd" "$2" "$3" 2>&1) || got="exit $?: $got"
  if [ "$got" != "$1" ]; then
    echo "FAIL: $(basename "$2") vs $(basename "$3"): expected '$1', got '$got'"
    fail=1
  fi
}
expect_exit() {  # CODE A B
  local rc=0
  bash "$fd" "$2" "$3" > /dev/null 2>&1 || rc=$?
  [ "$rc" -eq "$1" ] || { echo "FAIL: $(basename "$2") vs $(basename "$3"): exit $rc, not $1"; fail=1; }
}

header=l,U_b,wall_s,R_t
printf '%s\n0.1,1.5,0.01,nan\n0.2,2.25,0.02,nan\n0.3,3.125,0.03,4\n0.4,4,0.04,5\n' "$header" > "$tmp/a.csv"
# The same values, other wall times: equal.
printf '%s\n0.1,1.5,9,nan\n0.2,2.25,9,nan\n0.3,3.125,9,4\n0.4,4,9,5\n' "$header" > "$tmp/wall.csv"
# U_b differs in its last bit at l = 0.3 (3.1250000000000004 is the next double above 3.125).
printf '%s\n0.1,1.5,0.01,nan\n0.2,2.25,0.02,nan\n0.3,3.1250000000000004,0.03,4\n0.4,4,0.04,5\n' \
  "$header" > "$tmp/bit.csv"
# R_t is a number where A has NaN, at the first row.
printf '%s\n0.1,1.5,0.01,7\n0.2,2.25,0.02,nan\n' "$header" > "$tmp/nan.csv"
# A's first two rows only.
head -n 3 "$tmp/a.csv" > "$tmp/short.csv"
printf 'l,U_b,wall_s\n0.1,1.5,0.01\n' > "$tmp/cols.csv"

expect "equal to l = 0.4 (A ends at l = 0.4, B at l = 0.4)" "$tmp/a.csv" "$tmp/a.csv"
expect "equal to l = 0.4 (A ends at l = 0.4, B at l = 0.4)" "$tmp/a.csv" "$tmp/wall.csv"
expect "first difference at l = 0.3 (equal to l = 0.2; columns U_b)" "$tmp/a.csv" "$tmp/bit.csv"
expect "first difference at l = 0.1 (the first row; columns R_t)" "$tmp/a.csv" "$tmp/nan.csv"
expect "equal to l = 0.2 (A ends at l = 0.4, B at l = 0.2)" "$tmp/a.csv" "$tmp/short.csv"
expect "equal to l = 0.2 (A ends at l = 0.2, B at l = 0.4)" "$tmp/short.csv" "$tmp/a.csv"
expect_exit 2 "$tmp/a.csv" "$tmp/cols.csv"
expect_exit 2 "$tmp/a.csv" "$tmp/none.h5"

# --steps: one run recorded every 10 steps, the other every 5 (other l intervals); the rows at
# the same step count are compared.
printf 'l,U_b,wall_s,steps\n0,1,0.1,0\n1,2,0.2,10\n2,3,0.3,20\n3,4,0.4,30\n' > "$tmp/s10.csv"
printf 'l,U_b,wall_s,steps\n0,1,9,0\n0.5,1.5,9,5\n1,2,9,10\n1.5,2.5,9,15\n2,3,9,20\n' > "$tmp/s5.csv"
sed 's/^2,3,9,20$/2,3.0000000000000004,9,20/' "$tmp/s5.csv" > "$tmp/s5bit.csv"
expect_steps() {  # EXPECTED A B
  local got
  got=$(bash "$fd" --steps "$2" "$3" 2>&1) || got="exit $?: $got"
  [ "$got" = "$1" ] || { echo "FAIL: --steps $(basename "$2") vs $(basename "$3"): expected '$1', got '$got'"; fail=1; }
}
expect_steps "equal at 3 common steps, to l = 2 (A ends at l = 3, B at l = 2)" "$tmp/s10.csv" "$tmp/s5.csv"
expect_steps "first difference at step 20, l = 2 (equal at 2 earlier common steps; columns U_b)" \
  "$tmp/s10.csv" "$tmp/s5bit.csv"

# Real run files: one rigid scene to l = 3 and to l = 4 (the same run until the shorter ends),
# and with friction (its stick springs change the stability step from the start).
cd "$tmp"
echo '{"rho": 20, "mu_s": 0, "shell": "rigid", "l_max": 4}' > l4.json
echo '{"rho": 20, "mu_s": 0, "shell": "rigid", "l_max": 3}' > l3.json
echo '{"rho": 20, "mu_s": 0.5, "shell": "rigid", "l_max": 3}' > mu.json
for s in l4 l3 mu; do "$WIREPACK" run "$s.json" --out "$s.h5" > /dev/null 2>&1; done
# (l is recorded where the step lands, just past each multiple of 0.1.)
got=$(bash "$fd" l4.h5 l3.h5)
case "$got" in
  "equal to l = 3."*" (A ends at l = 4."*", B at l = 3."*")") ;;
  *) echo "FAIL: l4 vs l3: '$got'"; fail=1 ;;
esac
got=$(bash "$fd" l3.h5 mu.h5)
case "$got" in
  "first difference at l = "*"(the first row; columns"*" dt"*) ;;
  *) echo "FAIL: l3 vs mu: '$got'"; fail=1 ;;
esac
[ "$fail" -eq 0 ] && echo "first_difference.sh: all cases as expected"
exit "$fail"
