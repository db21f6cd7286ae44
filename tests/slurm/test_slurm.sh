#!/usr/bin/env bash
# SLURM job arrays end to end: scripts/slurm_sweep.sbatch, docs/reference.md's job-array script,
# on a real SLURM. Starts a one-node cluster of its own in a temporary directory (its own
# slurm.conf, munge key and socket, free ports; SlurmUser = the current user), then
#   1. submits the script as 3 array tasks over a tiny sweep (6 runs): every task completes,
#      each shard ran exactly its runs (index K mod 3), the union of the shards' run files is the
#      unsharded set, bitwise equal to an unsharded `wirepack sweep` run directly (series but
#      wall_s through `wirepack export --csv`, snapshots through h5diff), and the unsharded
#      command afterwards finds every run finished and runs nothing;
#   2. submits it over a slower sweep (12 runs of ~2 s), scancels the array once the first run is
#      finished, and submits it a third time: every run complete, the same set, the runs finished
#      before the scancel untouched (bytes and mtime), one joblog line per run, bitwise equal to
#      an unsharded reference.
# Stops the daemons and removes the directory at exit, whatever happens.
#   tests/slurm/test_slurm.sh WIREPACK_BINARY [SOURCE_DIR]     (ctest --test-dir build -L slurm)
# Exit 77 (ctest: skipped) when SLURM or MUNGE is not installed (scripts/install_slurm.sh).
# Environment: WIREPACK_SLURM_TIMEOUT seconds for each wait (default 120; a cluster that cannot
# start fails with the daemons' logs instead of hanging); WIREPACK_SLURM_KEEP=1 keeps the
# temporary directory; WIREPACK_SLURM_REQUIRED=1 (CI) fails instead of skipping without SLURM.
set -euo pipefail

say() { echo "test_slurm: [${SECONDS} s] $*"; }
failure=""
die() {
  failure=$*
  echo "test_slurm: FAIL: $*" >&2
  exit 1
}

[ $# -ge 1 ] || {
  echo "usage: $0 WIREPACK_BINARY [SOURCE_DIR]" >&2
  exit 2
}
wirepack=$(realpath "$1")
src=$(realpath "${2:-$(dirname "$0")/../..}")
job_script=$src/scripts/slurm_sweep.sbatch
timeout_s=${WIREPACK_SLURM_TIMEOUT:-120}
keep=${WIREPACK_SLURM_KEEP:-0}
required=${WIREPACK_SLURM_REQUIRED:-0}

for cmd in munged munge unmunge slurmctld slurmd sbatch squeue sinfo scancel scontrol; do
  if ! command -v "$cmd" >/dev/null; then
    [ "$required" = 1 ] && die "$cmd is not installed (scripts/install_slurm.sh)"
    say "SKIP: $cmd is not installed (scripts/install_slurm.sh installs SLURM and MUNGE)"
    exit 77
  fi
done
[ -x "$wirepack" ] || die "$wirepack: no wirepack binary (build the target wirepack)"
[ -f "$job_script" ] || die "$job_script: no job script"
command -v h5diff >/dev/null || die "h5diff not found (hdf5-tools, installed by scripts/setup.sh)"

# Nothing of an enclosing SLURM job or cluster leaks in (ctest itself may run inside a job).
while read -r v; do unset "$v"; done < <(compgen -e | grep '^SLURM_' || true)

tmp=$(mktemp -d "${TMPDIR:-/tmp}/wirepack-slurm.XXXXXX")
chmod 755 "$tmp" # munged wants every directory above its socket searchable by all
declare -A daemon # pid -> name, the daemons started here

show_logs() {
  local f
  for f in "$tmp"/log/*; do
    [ -s "$f" ] || continue
    echo "---- ${f#"$tmp"/} (last 25 lines)"
    tail -n 25 "$f"
  done
}

cleanup() {
  local rc=$? pid deadline
  set +e
  [ $rc -eq 0 ] || show_logs >&2
  if [ "${#daemon[@]}" -gt 0 ]; then
    # Jobs first (a job's slurmstepd outlives slurmd), then the daemons: scontrol shutdown, and
    # TERM, then KILL, to the ones still there.
    if [ -n "${SLURM_CONF:-}" ]; then
      timeout 15 scancel --user="$(id -un)" >/dev/null 2>&1
      deadline=$((SECONDS + 20))
      while [ $SECONDS -lt $deadline ] &&
        [ -n "$(timeout 10 squeue -h -o %i 2>/dev/null)" ]; do sleep 0.5; done
      timeout 15 scontrol shutdown >/dev/null 2>&1
    fi
    for pid in "${!daemon[@]}"; do
      [ "${daemon[$pid]}" = munged ] && continue
      deadline=$((SECONDS + 10))
      while kill -0 "$pid" 2>/dev/null && [ $SECONDS -lt $deadline ]; do sleep 0.2; done
    done
    for pid in "${!daemon[@]}"; do kill -TERM "$pid" 2>/dev/null; done
    for pid in "${!daemon[@]}"; do
      deadline=$((SECONDS + 10))
      while kill -0 "$pid" 2>/dev/null && [ $SECONDS -lt $deadline ]; do sleep 0.2; done
      kill -KILL "$pid" 2>/dev/null
      wait "$pid" 2>/dev/null
    done
  fi
  [ -z "$failure" ] || echo "test_slurm: FAIL: $failure (the logs are above)" >&2
  if [ "$keep" = 1 ]; then
    echo "test_slurm: kept $tmp" >&2
  else
    rm -rf "$tmp"
  fi
  exit $rc
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# wait_for WHAT COMMAND...: runs COMMAND every 0.2 s until it succeeds; fails after timeout_s
# seconds, or at once when a daemon started here has died, naming WHAT (the logs follow).
wait_for() {
  local what=$1 pid deadline=$((SECONDS + timeout_s))
  shift
  until "$@"; do
    for pid in "${!daemon[@]}"; do
      kill -0 "$pid" 2>/dev/null || die "${daemon[$pid]} exited while waiting for $what"
    done
    [ $SECONDS -lt $deadline ] || die "no $what after ${timeout_s} s"
    sleep 0.2
  done
}

port_in_use() { (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
free_port() { # a TCP port nothing listens on, other than $1
  local p i
  for i in $(seq 200); do
    p=$((20000 + RANDOM % 40000))
    if [ "$p" != "${1:-}" ] && ! port_in_use "$p"; then
      echo "$p"
      return 0
    fi
  done
  return 1
}

# ---- the cluster
mkdir -m 700 "$tmp/munge"
mkdir -m 755 "$tmp/run" "$tmp/log" "$tmp/state" "$tmp/spool"
head -c 1024 /dev/urandom >"$tmp/munge/munge.key"
chmod 400 "$tmp/munge/munge.key"
sock=$tmp/run/munge.sock
munged --foreground --key-file="$tmp/munge/munge.key" --socket="$sock" \
  --pid-file="$tmp/run/munged.pid" --log-file="$tmp/log/munged.log" \
  --seed-file="$tmp/munge/munged.seed" >"$tmp/log/munged.out" 2>&1 &
daemon[$!]=munged
munge_works() { munge -n -S "$sock" 2>/dev/null | unmunge -S "$sock" >/dev/null 2>&1; }
wait_for "munged answering on its socket" munge_works

ctld_port=$(free_port) || die "no free TCP port"
slurmd_port=$(free_port "$ctld_port") || die "no free TCP port"
user=$(id -un)
cpus=$(nproc)
export SLURM_CONF=$tmp/slurm.conf
cat >"$SLURM_CONF" <<EOF
# One-node cluster of tests/slurm/test_slurm.sh
ClusterName=wirepacktest
SlurmctldHost=localhost
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/run/slurmctld.pid
SlurmdPidFile=$tmp/run/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
MinJobAge=600
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -D -i -f "$SLURM_CONF" >"$tmp/log/slurmctld.out" 2>&1 &
daemon[$!]=slurmctld
slurmd -D -N localhost -f "$SLURM_CONF" >"$tmp/log/slurmd.out" 2>&1 &
daemon[$!]=slurmd
node_idle() { [ "$(timeout 15 sinfo -h -n localhost -o %t 2>/dev/null)" = idle ]; }
wait_for "idle node (sinfo)" node_idle
say "cluster up: $(slurmctld -V), 1 node of $cpus CPUs, ports $ctld_port/$slurmd_port, $tmp"

# ---- helpers
# submit SWEEP DIR: the repository's job script as 3 array tasks of 1 CPU; prints the job id.
submit() {
  local out
  out=$(cd "$tmp" && WIREPACK="$wirepack" timeout 30 sbatch --parsable --array=0-2 \
    --cpus-per-task=1 --output="$tmp/log/slurm-%A_%a.out" "$job_script" "$1" "$2") ||
    die "sbatch refused the job script: $out"
  echo "${out%%;*}"
}
job_done() { # no task of job $1 pending, running or completing
  local out
  out=$(timeout 15 squeue -h -j "$1" -o %T 2>/dev/null) || return 1
  [ -z "$out" ]
}
task_states() { # "TASK STATE EXITCODE" per array task of job $1, by task id
  timeout 15 scontrol -o show job "$1" |
    sed -E 's/.* ArrayTaskId=([^ ]+) .* JobState=([^ ]+) .* ExitCode=([^ ]+) .*/\1 \2 \3/' | sort -n
}
expect_completed() { # every task of job $1 completed with exit code 0
  local states
  states=$(task_states "$1")
  [ "$states" = $'0 COMPLETED 0:0\n1 COMPLETED 0:0\n2 COMPLETED 0:0' ] ||
    die "job $1: tasks not all COMPLETED with exit code 0:"$'\n'"$states"
}
run_files() { # sorted names of the finished run files in DIR/runs
  local f
  for f in "$1"/runs/*.h5; do if [ -e "$f" ]; then basename "$f"; fi; done | sort
}
count_runs() { run_files "$1" | wc -l; }
at_least_one_run() { [ "$(count_runs "$1")" -ge 1 ]; }
planned_files() { # run files of sweep $1 in run order (wirepack validate)
  "$wirepack" validate "$1" | sed -n -E 's|^ *"file": "runs/(.*)",?$|\1|p'
}
series_csv() { # series of run file $1 but wall_s, as wirepack export --csv writes them, into $2
  "$wirepack" export "$1" --csv "$2.full" >/dev/null
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "wall_s") w = i; if (!w) exit 3 }
           { s = ""; for (i = 1; i <= NF; i++) if (i != w) { printf "%s%s", s, $i; s = "," }
             print "" }' "$2.full" >"$2"
}
# same_runs REF DIR: every run file of REF has its twin in DIR with bitwise equal series (all but
# wall_s) and snapshots.
same_runs() {
  local f
  mkdir -p "$tmp/csv"
  for f in $(run_files "$1"); do
    series_csv "$1/runs/$f" "$tmp/csv/a.csv" || die "$1/runs/$f: export failed"
    series_csv "$2/runs/$f" "$tmp/csv/b.csv" || die "$2/runs/$f: export failed"
    cmp -s "$tmp/csv/a.csv" "$tmp/csv/b.csv" || die "$2/runs/$f: series differ from $1/runs/$f"
    h5diff "$1/runs/$f" "$2/runs/$f" /snapshots /snapshots >/dev/null ||
      die "$2/runs/$f: snapshots differ from $1/runs/$f"
  done
}
# joblog_files DIR K: files of the complete runs in shard K's joblog (of 3), sorted
joblog_files() {
  tail -n +2 "$1/joblog.shard-$2-of-3.csv" | awk -F, -v k="$2/3" '$6 == "complete" && $8 == k {
    sub(/^runs\//, "", $2); print $2 }' | sort
}
# unsharded_runs_nothing SWEEP DIR N: the unsharded command after the array finds all N runs
# finished, runs nothing, touches no run file and writes the combined manifest.
unsharded_runs_nothing() {
  local before after
  before=$(cd "$2/runs" && stat -c '%n %s %y' ./*.h5)
  "$wirepack" sweep "$1" --out "$2" >"$tmp/log/unsharded.out" 2>&1 ||
    die "unsharded wirepack sweep after the array failed: $(cat "$tmp/log/unsharded.out")"
  after=$(cd "$2/runs" && stat -c '%n %s %y' ./*.h5)
  [ "$before" = "$after" ] || die "$2: the unsharded command touched run files"
  [ "$(tail -n +2 "$2/joblog.csv" 2>/dev/null | wc -l)" -eq 0 ] ||
    die "$2: the unsharded command ran runs (joblog.csv): $(cat "$2/joblog.csv")"
  if ! grep -q "\"complete\": $3," "$2/manifest.json" || ! grep -q "\"runs\": $3\$" "$2/manifest.json"; then
    die "$2/manifest.json: not $3 of $3 complete"
  fi
}

# ---- 1. a tiny sweep (6 runs of ~10 ms), 3 tasks, against an unsharded reference
cat >"$tmp/fast.sweep.json" <<'EOF'
{
  "name": "slurm_fast",
  "base": { "rho": 10, "shell": "rigid", "l_max": 2, "numerics": { "element_length": 1e-3 } },
  "grid": { "mu_s": [0, 0.5] },
  "seeds": 3,
  "analysis": {}
}
EOF
"$wirepack" sweep "$tmp/fast.sweep.json" --out "$tmp/fast_ref" >"$tmp/log/fast_ref.out" 2>&1 ||
  die "reference sweep failed: $(cat "$tmp/log/fast_ref.out")"
mapfile -t planned < <(planned_files "$tmp/fast.sweep.json")
[ "${#planned[@]}" -eq 6 ] || die "wirepack validate lists ${#planned[@]} runs, not 6"

job=$(submit "$tmp/fast.sweep.json" "$tmp/fast")
say "1. job array $job: 3 tasks over 6 runs"
wait_for "end of job array $job (squeue)" job_done "$job"
expect_completed "$job"
for k in 0 1 2; do
  [ -f "$tmp/fast/manifest.shard-$k-of-3.json" ] || die "no manifest.shard-$k-of-3.json"
  expected=$(for i in "${!planned[@]}"; do if [ $((i % 3)) -eq $k ]; then echo "${planned[$i]}"; fi; done | sort)
  [ "$(joblog_files "$tmp/fast" "$k")" = "$expected" ] ||
    die "task $k did not run exactly the runs of shard $k/3 (index $k mod 3):"$'\n'"$(cat "$tmp/fast/joblog.shard-$k-of-3.csv")"
done
[ ! -e "$tmp/fast/manifest.json" ] || die "an array task wrote the unsharded manifest.json"
[ "$(run_files "$tmp/fast")" = "$(printf '%s\n' "${planned[@]}" | sort)" ] ||
  die "the shards' run files are not the sweep's runs: $(run_files "$tmp/fast")"
[ "$(run_files "$tmp/fast")" = "$(run_files "$tmp/fast_ref")" ] || die "not the reference's run files"
same_runs "$tmp/fast_ref" "$tmp/fast"
unsharded_runs_nothing "$tmp/fast.sweep.json" "$tmp/fast" 6
say "1. ok: tasks 0-2 COMPLETED, shard K ran exactly the runs K mod 3, union = the 6 runs of the" \
  "unsharded sweep, series (but wall_s) and snapshots bitwise equal to it; the unsharded" \
  "command afterwards ran nothing"

# ---- 2. a slower sweep (12 runs of ~2 s): scancel mid-way, then a third submission
cat >"$tmp/slow.sweep.json" <<'EOF'
{
  "name": "slurm_slow",
  "base": { "rho": 10, "shell": "rigid", "mu_s": 0, "l_max": 30,
            "numerics": { "element_length": 1e-3 } },
  "grid": {},
  "seeds": 12,
  "analysis": {}
}
EOF
mapfile -t planned < <(planned_files "$tmp/slow.sweep.json")
[ "${#planned[@]}" -eq 12 ] || die "wirepack validate lists ${#planned[@]} runs, not 12"
job=$(submit "$tmp/slow.sweep.json" "$tmp/slow")
submitted=$SECONDS
say "2. job array $job: 3 tasks over 12 runs"
wait_for "first finished run of job array $job" at_least_one_run "$tmp/slow"
timeout 30 scancel "$job" || die "scancel $job failed"
cancelled=$((SECONDS - submitted))
wait_for "end of the cancelled job array $job (squeue)" job_done "$job"
states=$(task_states "$job")
grep -q CANCELLED <<<"$states" || die "job $job: no task cancelled:"$'\n'"$states"
done_before=$(count_runs "$tmp/slow")
[ "$done_before" -lt 12 ] || die "every run finished before the scancel (runs too short)"
mapfile -t finished < <(run_files "$tmp/slow")
fingerprint() { (cd "$tmp/slow/runs" && stat -c '%n %s %y' "${finished[@]}" && md5sum "${finished[@]}"); }
before=$(fingerprint)
say "2. scancel $job ${cancelled} s after sbatch, $done_before of 12 runs finished; tasks: ${states//$'\n'/, }"

job=$(submit "$tmp/slow.sweep.json" "$tmp/slow")
say "2. job array $job: the same 3 tasks again"
wait_for "end of job array $job (squeue)" job_done "$job"
expect_completed "$job"
[ "$(run_files "$tmp/slow")" = "$(printf '%s\n' "${planned[@]}" | sort)" ] ||
  die "after the third submission the run files are not the sweep's 12 runs: $(run_files "$tmp/slow")"
[ -z "$(find "$tmp/slow" -name '*.part' -o -name '*.tmp.*')" ] || die "leftovers: $(find "$tmp/slow" -name '*.part' -o -name '*.tmp.*')"
after=$(fingerprint)
[ "$before" = "$after" ] ||
  die "runs finished before the scancel were changed:"$'\n'"$before"$'\n'"$after"
lines=$(for k in 0 1 2; do tail -n +2 "$tmp/slow/joblog.shard-$k-of-3.csv"; done | awk -F, '$6 == "complete" { print $2 }' | sort)
[ "$lines" = "$(printf 'runs/%s\n' "${planned[@]}" | sort)" ] ||
  die "not exactly one complete joblog line per run:"$'\n'"$lines"
"$wirepack" sweep "$tmp/slow.sweep.json" --out "$tmp/slow_ref" >"$tmp/log/slow_ref.out" 2>&1 ||
  die "reference sweep failed: $(cat "$tmp/log/slow_ref.out")"
same_runs "$tmp/slow_ref" "$tmp/slow"
unsharded_runs_nothing "$tmp/slow.sweep.json" "$tmp/slow" 12
say "2. ok: after scancel and a third submission tasks 0-2 COMPLETED, all 12 runs complete (the" \
  "unsharded set), the $done_before finished before the scancel untouched, one joblog line per" \
  "run, bitwise equal to an unsharded reference; the unsharded command afterwards ran nothing"
say "PASS"
