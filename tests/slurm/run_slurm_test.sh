#!/usr/bin/env bash
# Integration test of `fsweep slurm` against a real Slurm: starts a private single-node Slurm
# (Debian's slurm-wlm and munge) on this host, runs the sweep tests/slurm/slurm_test_sweep.json
# (12 runs) through `fsweep slurm` twice -- 4 shards as 4 array tasks, and 4 shards packed into
# 3 tasks (--max-array-size 3) -- then redoes one deleted shard by resubmitting its array index
# alone, and checks that each merged result equals a local `fsweep run` apart from the timing
# columns (*_time_s). The first submission also passes --account, --qos, two --sbatch lines and
# a --setup line, and checks that they reach the jobs (step 5b). Everything it starts (munged, slurmctld, slurmd, jobs) runs from a
# temporary directory with its own config, socket and ports, and is stopped and removed on exit.
#
#   tests/slurm/run_slurm_test.sh [FSWEEP]    # FSWEEP: default $FSWEEP, else build/release/bin/fsweep
#
# Needs root (slurmd launches the jobs). Installs slurm-wlm and munge when missing
# (scripts/bootstrap slurm). Prints PASS or FAIL; exit 0 pass, 1 fail, 77 cannot run (skip).
set -uo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
fsweep=${1:-${FSWEEP:-$root/build/release/bin/fsweep}}
sweep=$here/slurm_test_sweep.json
start_s=$(date +%s)
timeout_s=${FSWEEP_SLURM_TEST_TIMEOUT:-180}  # per wait for jobs or the node

skip() {
  echo "SKIP: $*"
  exit 77
}
fail() {
  echo "FAIL: $*"
  exit 1
}
log() { echo "[$(($(date +%s) - start_s)) s] $*"; }

[ -x "$fsweep" ] || fail "no fsweep executable at $fsweep (build it, or pass its path)"
fsweep=$(cd "$(dirname "$fsweep")" && pwd)/$(basename "$fsweep")
command -v python3 >/dev/null || skip "python3 is needed for the comparison"

# 1. Packages.
have_slurm() { command -v slurmctld && command -v slurmd && command -v sbatch && command -v munged; } >/dev/null
if [ "$(id -u)" -ne 0 ]; then
  skip "needs root to run slurmd (and to install slurm-wlm and munge); run it as root, e.g. sudo $0"
fi
if ! have_slurm; then
  log "installing slurm-wlm and munge (scripts/bootstrap slurm)"
  "$root/scripts/bootstrap" slurm || skip "could not install slurm-wlm and munge (scripts/bootstrap slurm failed)"
  have_slurm || skip "slurm-wlm and munge are still missing after scripts/bootstrap slurm"
  log "installed"
fi

# 2. A private single-node Slurm.
tmp=$(mktemp -d /tmp/fsweep-slurm-test.XXXXXX) || fail "mktemp failed"
chmod 0700 "$tmp"
export SLURM_CONF=$tmp/slurm.conf

# Processes started by this test: the daemons (pid files) and every process that inherited
# our SLURM_CONF (slurmstepd, job scripts, fsweep), found by pid through /proc/<pid>/environ.
our_pids() {
  local f pid
  for f in /proc/[0-9]*/environ; do
    pid=${f#/proc/}
    pid=${pid%/environ}
    [ "$pid" = $$ ] || [ "$pid" = "$BASHPID" ] && continue
    if { tr '\0' '\n' <"$f"; } 2>/dev/null | grep -qxF "SLURM_CONF=$SLURM_CONF"; then echo "$pid"; fi
  done
}
stop_pidfile() {  # stop_pidfile FILE: SIGTERM the daemon, wait up to 10 s, then SIGKILL
  local pid
  [ -s "$1" ] || return 0
  pid=$(cat "$1")
  kill -TERM "$pid" 2>/dev/null || return 0
  for _ in $(seq 50); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.2
  done
  kill -KILL "$pid" 2>/dev/null
}
cleanup() {
  local rc=$? pids
  trap - EXIT INT TERM
  if [ -s "$tmp/slurmctld.pid" ]; then
    scancel --quiet --full "--user=$(id -un)" >/dev/null 2>&1 || true
  fi
  stop_pidfile "$tmp/slurmd.pid"
  stop_pidfile "$tmp/slurmctld.pid"
  pids=$(our_pids)
  # shellcheck disable=SC2086
  [ -n "$pids" ] && kill -KILL $pids 2>/dev/null
  stop_pidfile "$tmp/munge/munged.pid"
  if [ "$rc" -ne 0 ] && [ -n "${FSWEEP_SLURM_TEST_KEEP:-}" ]; then
    echo "kept $tmp for inspection (FSWEEP_SLURM_TEST_KEEP)"
  else
    rm -rf "$tmp"
  fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

show_logs() {
  local f
  for f in "$tmp"/slurmctld.log "$tmp"/slurmd.log "$tmp"/munge/munged.log "$@"; do
    [ -f "$f" ] && { echo "--- tail of $f"; tail -n 25 "$f"; }
  done
}

free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }

host=$(hostname -s)
getent hosts "$host" >/dev/null || skip "the host name $host does not resolve (add it to /etc/hosts)"
mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool"
chmod 0700 "$tmp/munge"
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 0400 "$tmp/munge/munge.key"
munged --force --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/munge.socket" \
  --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/munge/munged.log" --seed-file="$tmp/munge/munged.seed" ||
  { show_logs; fail "munged did not start"; }
cpus=$(nproc)
cat >"$SLURM_CONF" <<EOF
# Private single-node cluster of tests/slurm/run_slurm_test.sh
ClusterName=fsweeptest
SlurmctldHost=$host
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=256 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld || { show_logs; fail "slurmctld did not start"; }
slurmd || { show_logs; fail "slurmd did not start"; }

wait_until() {  # wait_until WHAT COMMAND...: poll every 0.5 s until COMMAND succeeds
  local what=$1 deadline=$(($(date +%s) + timeout_s))
  shift
  until "$@"; do
    if [ "$(date +%s)" -ge "$deadline" ]; then
      show_logs
      fail "timed out after ${timeout_s} s waiting for $what"
    fi
    sleep 0.5
  done
}
node_idle() { [ "$(sinfo -h -N -o %T 2>/dev/null)" = idle ]; }
no_jobs() { [ -z "$(squeue -h -o %i 2>/dev/null)" ] && squeue -h >/dev/null 2>&1; }
wait_until "the node to be idle" node_idle
log "single-node Slurm up: node $host idle, $cpus CPUs"

# 3. The sweep through Slurm: 4 array tasks, and 4 shards packed into 3 tasks.
submit() {  # submit OUT ARGS...: fsweep slurm; sets array_id and merge_id
  local out=$1
  shift
  "$fsweep" slurm "$sweep" --out "$out" "$@" >"$out.log" 2>&1 || { cat "$out.log"; fail "fsweep slurm $* failed"; }
  array_id=$(sed -n 's/^submitted array job \([0-9]*\).*/\1/p' "$out.log")
  merge_id=$(sed -n 's/^submitted merge job \([0-9]*\).*/\1/p' "$out.log")
  if [ -z "$array_id" ] || [ -z "$merge_id" ]; then
    cat "$out.log"
    fail "fsweep slurm $* did not submit two jobs"
  fi
}
job_states() {  # job_states ID: the JobState of each of the job's (array) records, sorted
  scontrol -o show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort | uniq -c | tr -s ' ' | tr '\n' ';'
}
expect_completed() {  # expect_completed ID COUNT
  local s
  s=$(job_states "$1")
  [ "$s" = " $2 COMPLETED;" ] || { show_logs "$tmp"/out*/slurm/logs/*; fail "job $1: states '$s', expected $2 COMPLETED"; }
}

mkdir -p "$tmp/out_array" "$tmp/out_packed" "$tmp/setup"
# The cluster options on the first sweep: an --sbatch line in each accepted form (--comment is
# recorded by slurmctld; --export puts a variable into the jobs' environment), and a --setup
# line that writes a file per job with that variable, so both are seen to take effect in the
# jobs. --account and --qos: this Slurm has no accounting (AccountingStorageType=
# accounting_storage/none), so it accepts any account and records it as given, and accepts a
# QOS without recording it (the job shows QOS=(null): there is no QOS table without the
# accounting database). Checked here: sbatch takes both directives and the account reaches the
# job. Not checkable here: a cluster with accounting refusing an account or QOS the user may
# not use (AccountingStorageEnforce), and the QOS the job then runs with.
# shellcheck disable=SC2016  # $FSWEEP_..., $SLURM_... are for the jobs' shell
submit "$tmp/out_array" --tasks 4 --account fsweep-test --qos normal \
  --sbatch --comment=fsweep-slurm-test --sbatch '#SBATCH --export=ALL,FSWEEP_SLURM_TEST_SBATCH=from-sbatch-line' \
  --setup 'echo "setup ran, sbatch line ${FSWEEP_SLURM_TEST_SBATCH:-not seen}" >'"$tmp"'/setup/job_${SLURM_ARRAY_TASK_ID:-merge}'
a1=$array_id m1=$merge_id
grep -q "^array: 4 tasks (MaxArraySize 1001, from scontrol show config), one shard each" "$tmp/out_array.log" ||
  { cat "$tmp/out_array.log"; fail "fsweep slurm --tasks 4 did not plan 4 array tasks from scontrol"; }
submit "$tmp/out_packed" --tasks 4 --max-array-size 3
a2=$array_id m2=$merge_id
grep -q "^array: 3 tasks (MaxArraySize 3, from --max-array-size); packed" "$tmp/out_packed.log" ||
  { cat "$tmp/out_packed.log"; fail "fsweep slurm --tasks 4 --max-array-size 3 did not pack into 3 tasks"; }
log "submitted array $a1 + merge $m1 (4 tasks), array $a2 + merge $m2 (3 tasks, packed)"
wait_until "jobs $a1 $m1 $a2 $m2 to finish" no_jobs
expect_completed "$a1" 4
expect_completed "$m1" 1
expect_completed "$a2" 3
expect_completed "$m2" 1
grep -q "shard 3/4" "$tmp"/out_packed/slurm/logs/"${a2}"_0.out ||
  fail "packed array task 0 did not run shard 3/4 (log: $(cat "$tmp"/out_packed/slurm/logs/"${a2}"_0.out))"
log "all jobs completed"

# 4. The same sweep locally.
"$fsweep" run "$sweep" --out "$tmp/local" --quiet >"$tmp/local.log" 2>&1 || { cat "$tmp/local.log"; fail "local run failed"; }

# 5. Merged outputs equal the local run's, apart from timing columns.
compare() {  # compare DIR: runs.csv, progress.csv, summary.csv, best.csv of DIR vs the local run
  python3 - "$1" "$tmp/local" <<'PY'
import csv, re, sys
timing = re.compile(r"_time_s(\.|$)")  # runs.csv: wall_time_s, ...; summary.csv: wall_time_s.mean, ...
def table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    keep = [i for i, name in enumerate(rows[0]) if not timing.search(name)]
    return [[r[i] for i in keep] for r in rows], len(rows[0]) - len(keep)
bad = 0
for name in ("runs.csv", "progress.csv", "summary.csv", "best.csv"):
    got, dropped = table(f"{sys.argv[1]}/{name}")
    want, _ = table(f"{sys.argv[2]}/{name}")
    if got != want:
        bad += 1
        diff = next((i for i, (g, w) in enumerate(zip(got, want)) if g != w), min(len(got), len(want)))
        print(f"{sys.argv[1]}/{name}: differs from the local run at row {diff} ({len(got)} vs {len(want)} rows)")
    else:
        print(f"{sys.argv[1]}/{name}: {len(got) - 1} rows equal to the local run ({dropped} timing columns ignored)")
sys.exit(1 if bad else 0)
PY
}
compare "$tmp/out_array" || fail "the 4-task merge differs from the local run"
compare "$tmp/out_packed" || fail "the packed merge differs from the local run"

# 5b. The cluster options of the first sweep: the setup line ran in every job (4 array tasks and
# the merge) before fsweep, and saw the variable of the --sbatch --export line; slurmctld
# recorded the --sbatch --comment line and the account on both jobs; the QOS is in both
# scripts (this Slurm does not record it, above).
for job in 0 1 2 3 merge; do
  got=$(cat "$tmp/setup/job_$job" 2>/dev/null)
  [ "$got" = "setup ran, sbatch line from-sbatch-line" ] ||
    { show_logs "$tmp"/out_array/slurm/logs/*; fail "job $job: the --setup line wrote '$got' ($tmp/setup/job_$job)"; }
done
for id in "$a1" "$m1"; do
  record=$(scontrol -o show job "$id" | head -n 1)
  for field in Comment=fsweep-slurm-test Account=fsweep-test; do
    case " $record " in
      *" $field "*) ;;
      *) fail "job $id: no $field in its record ($record)" ;;
    esac
  done
  log "job $id: $(echo "$record" | grep -o 'Account=[^ ]* QOS=[^ ]*')"
done
for script in array merge; do
  grep -qx -- '#SBATCH --qos=normal' "$tmp/out_array/slurm/$script.sbatch" || fail "no --qos line in $script.sbatch"
done
log "--setup ran in all 5 jobs, --sbatch lines took effect, account recorded"

# 6. A lost shard: merge reports it, resubmitting its array index alone redoes it.
rm -rf "$tmp/out_array/shard-2-of-4" "$tmp/out_array/runs.csv" "$tmp/out_array/summary.csv"
if "$fsweep" merge "$tmp/out_array" >"$tmp/merge_missing.log" 2>&1; then
  fail "fsweep merge succeeded with shard 2 of 4 deleted"
fi
grep -q "shard-2-of-4" "$tmp/merge_missing.log" || { cat "$tmp/merge_missing.log"; fail "merge did not name the missing shard"; }
a3=$(sbatch --parsable --array=2 "$tmp/out_array/slurm/array.sbatch") || fail "resubmitting array index 2 failed"
m3=$(sbatch --parsable "--dependency=afterany:$a3" "$tmp/out_array/slurm/merge.sbatch") || fail "resubmitting the merge failed"
wait_until "resubmitted jobs $a3 $m3 to finish" no_jobs
expect_completed "$a3" 1
expect_completed "$m3" 1
compare "$tmp/out_array" || fail "the merge after resubmitting shard 2 differs from the local run"
log "resubmitted array index 2 alone: merged again, equal"

echo "PASS: Slurm integration test ($(($(date +%s) - start_s)) s)"
