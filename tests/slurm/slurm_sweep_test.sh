#!/usr/bin/env bash
# A sweep on a real Slurm (scripts/slurm-sweep), against a single-node Slurm this test starts
# (scripts/slurm-local) in its own scratch folder, with its own configuration, key and free
# loopback ports:
#   1. `experiment split` on the Sun-3/60 for two small scenes and two methods, run here: the
#      reference table;
#   2. the same runs emitted as jobs and submitted as an array with the join after it; one task
#      is cancelled while its run is under way: it writes nothing, and the join does not run;
#   3. submitted again, the array recomputes only the cancelled run and the join's table equals
#      the reference byte for byte (every column is counted or modelled from counts);
#   4. a job file past sbatch's 4 MB script limit: its lines packed into the task script, each
#      run once.
# The daemons it started are stopped by their process ids on success and failure alike; their
# logs are printed when it fails. Exit 77 (skipped) only when Slurm is not installed.
#
#   tests/slurm/slurm_sweep_test.sh FB89 SOURCE-DIR
set -uo pipefail
fb89="$1"
src="$2"

if [ -z "$(PATH="$PATH:/usr/sbin" type -P slurmctld)" ] || [ -z "$(type -P sbatch)" ] ||
   [ -z "$(PATH="$PATH:/usr/sbin" type -P munged)" ]; then
  echo "SKIP: Slurm is not installed (Debian's slurm-wlm and munge; scripts/bootstrap installs them)"
  exit 77
fi

# mktemp's folder is the test's scratch: short enough for munged's socket path, removed at the end
scratch="$(mktemp -d "${TMPDIR:-/tmp}/fb89-slurm.XXXXXX")" || exit 1
chmod 0755 "$scratch"  # munged wants every folder above its socket world-executable
slurm="$scratch/slurm"
failed=0
step=""

fail() {
  echo "FAILED ($step): $1" >&2
  failed=1
  exit 1
}

cleanup() {
  local rc=$?
  [ "$failed" = 1 ] && rc=1
  local ctld
  ctld="$(cat "$slurm/slurmctld.pid.started" 2>&1)"
  if [ -f "$slurm/slurm.conf" ] && [ -n "$ctld" ] && [ -d "/proc/$ctld" ]; then
    # nothing of ours left running: every job of this private cluster, then its daemons
    export SLURM_CONF="$slurm/slurm.conf"
    timeout 10 scancel --user="$(id -un)" > "$scratch/scancel.out" 2>&1
    for _ in $(seq 50); do
      [ -z "$(timeout 5 squeue -h -o %i 2>&1)" ] && break
      sleep 0.2
    done
  fi
  local pids=""
  for d in munged slurmctld slurmd; do
    pids+=" $(cat "$slurm/$d.pid.started" 2>&1)"
  done
  if [ "$rc" != 0 ]; then
    "$src/scripts/slurm-local" logs "$slurm" >&2
    for f in "$scratch"/runs/slurm/*.out; do
      [ -f "$f" ] && { echo "--- $f"; cat "$f"; } >&2
    done
  fi
  "$src/scripts/slurm-local" stop "$slurm"
  for pid in $pids; do
    case "$pid" in *[!0-9]* | '') continue ;; esac
    if [ -d "/proc/$pid" ] && tr '\0' ' ' < "/proc/$pid/cmdline" | grep -qF "$slurm/"; then
      echo "FAILED: daemon $pid still runs after the stop" >&2
      rc=1
    fi
  done
  rm -rf "$scratch"
  exit "$rc"
}
trap cleanup EXIT

step="start the single-node Slurm"
"$src/scripts/slurm-local" start "$slurm" --cpus 2 > "$scratch/start.out" 2>&1 ||
  { cat "$scratch/start.out" >&2; fail "scripts/slurm-local start failed"; }
export SLURM_CONF="$slurm/slurm.conf"
grep -qx "export SLURM_CONF=$slurm/slurm.conf" "$scratch/start.out" || fail "start printed $(cat "$scratch/start.out")"

cd "$scratch" || exit 1
# the scan-line runs take a fraction of a second, the ray tracer's several: one of those is cancelled
split=("$fb89" experiment split A B --methods scanline raytrace --size 512x390 --host sun3-60 -q)

step="the reference, run here"
"${split[@]}" --jobs 2 --results "$scratch/local" --csv "$scratch/local.csv" || fail "local run"

step="emit the jobs"
"${split[@]}" --results "$scratch/runs" --emit-jobs "$scratch/jobs.txt" 2> "$scratch/emit.err" ||
  fail "emit: $(cat "$scratch/emit.err")"
[ "$(grep -c . "$scratch/jobs.txt")" = 4 ] || fail "4 runs expected, jobs: $(cat "$scratch/jobs.txt")"
grep -q "scripts/slurm-sweep" "$scratch/emit.err" || fail "emit does not name slurm-sweep: $(cat "$scratch/emit.err")"

join=("${split[@]}" --results "$scratch/runs" --csv "$scratch/cluster.csv")

step="usage"
"$src/scripts/slurm-sweep" "$scratch/jobs.txt" > "$scratch/usage.out" 2>&1
[ $? = 2 ] && grep -q "give the join command after --" "$scratch/usage.out" ||
  fail "a missing join command: $(cat "$scratch/usage.out")"

step="submit, and cancel a task while its run is under way"
"$src/scripts/slurm-sweep" --throttle 2 --time=10:00 "$scratch/jobs.txt" -- "${join[@]}" \
  > "$scratch/submit.out" 2>&1 || fail "slurm-sweep: $(cat "$scratch/submit.out")"
array="$(sed -n 's/.* as array job \([0-9]*\) .*/\1/p' "$scratch/submit.out")"
joinid="$(sed -n 's/.*the join as job \([0-9]*\) .*/\1/p' "$scratch/submit.out")"
[ -n "$array" ] && [ -n "$joinid" ] || fail "no job ids in: $(cat "$scratch/submit.out")"
grep -q "squeue -j $array,$joinid" "$scratch/submit.out" || fail "no squeue line: $(cat "$scratch/submit.out")"
t="$(grep -n "'--method' 'raytrace'" "$scratch/jobs.txt" | head -1 | cut -d: -f1)"
[ -n "$t" ] || fail "no ray tracer's run among the jobs"
victim="${array}_$t"
for _ in $(seq 300); do  # until its emulated run has begun (at most 30 s)
  grep -q "^slurm-sweep task $t on .*: run" "$scratch/runs/slurm/task-$victim.out" 2>&1 && break
  sleep 0.1
done
sleep 1  # inside its emulated run (about 4 s)
[ "$(squeue -h -j "$victim" -o %T 2>&1)" = RUNNING ] ||
  fail "task $victim is not running: $(squeue 2>&1; cat "$scratch/runs/slurm/task-$victim.out")"
scancel "$victim" || fail "scancel $victim"
for _ in $(seq 600); do  # until the array and the join have left the queue (at most 60 s)
  [ -z "$(squeue -h -j "$array,$joinid" -o %i 2>&1)" ] && break
  sleep 0.1
done
[ -z "$(squeue -h -j "$array,$joinid" -o %i 2>&1)" ] || fail "still queued: $(squeue 2>&1)"
vlog="$scratch/runs/slurm/task-$victim.out"
grep -q "fb89 host-run: stopped by SIGTERM before the run ended; nothing written" "$vlog" ||
  fail "the cancelled task did not say it wrote nothing: $(cat "$vlog")"
counts=()
for f in "$scratch"/runs/*.json; do
  case "$(basename "$f")" in work-*) ;; *) counts+=("$f") ;; esac
done
[ "${#counts[@]}" = 3 ] || fail "3 runs expected in the results after the cancel, found ${#counts[@]}"
[ -z "$(find "$scratch/runs" -maxdepth 1 -name '.*tmp*')" ] || fail "a temporary left: $(ls -a "$scratch/runs")"
[ ! -e "$scratch/cluster.csv" ] || fail "the join ran although a task was cancelled"
[ ! -e "$scratch/runs/slurm/join-$joinid.status" ] || fail "the join ran although a task was cancelled"

step="submit again and wait"
"$src/scripts/slurm-sweep" --wait "$scratch/jobs.txt" -- "${join[@]}" > "$scratch/again.out" 2>&1 ||
  fail "second slurm-sweep: $(cat "$scratch/again.out")"
array2="$(sed -n 's/.* as array job \([0-9]*\) .*/\1/p' "$scratch/again.out")"
[ -n "$array2" ] || fail "no job id in: $(cat "$scratch/again.out")"
ran=0 kept=0
for t in 1 2 3 4; do
  log="$scratch/runs/slurm/task-${array2}_$t.out"
  grep -q "^slurm-sweep task $t: done$" "$log" || fail "task $t of $array2 not done: $(cat "$log")"
  if grep -q "is there already: not run again" "$log"; then kept=$((kept + 1)); else ran=$((ran + 1)); fi
done
[ "$ran" = 1 ] && [ "$kept" = 3 ] || fail "the second array ran $ran runs and kept $kept; 1 and 3 expected"
[ -f "$scratch/cluster.csv" ] || fail "no joined table"
cmp "$scratch/local.csv" "$scratch/cluster.csv" ||
  fail "the joined table differs from the local run's: $(diff "$scratch/local.csv" "$scratch/cluster.csv")"
[ "$(grep -c . "$scratch/cluster.csv")" = 5 ] || fail "a header and 4 rows expected: $(cat "$scratch/cluster.csv")"

step="a job file past sbatch's 4 MB"
# 1,200 lines of 4 KB each, 4.9 MB (as big as some 16,000 emitted runs of 300 bytes): each
# run touches its own file. Over 4 MB of script sbatch refuses ("Pathname ... too long"), so
# slurm-sweep packs the lines; every one must still run, once
big="$scratch/big"
mkdir -p "$big" || exit 1
pad="$(printf '%04000d' 0)"
for i in $(seq 1200); do
  echo "bash -c 'touch $big/ran.$i' --results $big # $pad"
done > "$scratch/big.txt"
[ "$(stat -c %s "$scratch/big.txt")" -gt 4194304 ] || fail "the job file is not past 4 MB"
"$src/scripts/slurm-sweep" --per-task 300 --wait "$scratch/big.txt" -- touch "$big/joined" \
  > "$scratch/big.out" 2>&1 || fail "slurm-sweep: $(cat "$scratch/big.out")"
[ "$(stat -c %s "$scratch/big.txt.sbatch")" -lt 4194304 ] || fail "the task script is not under 4 MB"
[ -f "$big/joined" ] || fail "the join did not run: $(cat "$scratch/big.out")"
ran="$(find "$big" -maxdepth 1 -name 'ran.*' | wc -l)"
[ "$ran" = 1200 ] || fail "$ran of the 1200 runs ran"
[ "$(cat "$big"/slurm/task-*.out | grep -c '^slurm-sweep task .* on .*: run ')" = 1200 ] ||
  fail "not one run each: $(cat "$big"/slurm/task-*.out | head)"

step="a task script past the cluster's own limit"
# a cluster that takes at most 1,000 bytes of script (its scontrol says so): refused, naming
# the sizes, before anything is submitted (--dry-run would print the sbatch lines)
mkdir -p "$scratch/bin" || exit 1
printf '#!/bin/sh\necho "SchedulerParameters     = max_script_size=1000"\n' > "$scratch/bin/scontrol"
chmod +x "$scratch/bin/scontrol"
PATH="$scratch/bin:$PATH" "$src/scripts/slurm-sweep" --dry-run "$scratch/jobs.txt" -- true \
  > "$scratch/limit.out" 2>&1
[ $? = 1 ] && grep -q "bytes, more than sbatch takes (max_script_size 1000)" "$scratch/limit.out" &&
  ! grep -q "^sbatch" "$scratch/limit.out" || fail "not refused: $(cat "$scratch/limit.out")"

echo "slurm sweep: 4 runs on array $array (task $victim cancelled, nothing written), array $array2" \
     "recomputed 1 and kept 3; the joined table equals the local run's; 1,200 runs from a"\
     "4.9 MB job file, packed, ran once each"
