#!/usr/bin/env bash
# A study on a real Slurm cluster: scripts/slurm-local.sh starts a one-node cluster on this
# machine (munge, slurmctld, slurmd), `compare --slurm` submits a tiny study as a job array
# and its merge job, two tasks are killed on purpose in the middle of their unit
# (SUNGLINT_TEST_KILL_TASKS: the process SIGKILLs itself, as the OOM killer would), the same
# command run again resubmits exactly the two missing units and the merge, and the result
# equals a local run: the same frames byte for byte, the same results.json numbers; then
# `render --slurm` over a frame range, and again for a frame removed. The cluster is stopped
# on every exit, failures included.
#
# Exit 77 (skipped) when slurm-wlm or munge is not installed, unless SUNGLINT_REQUIRE_SLURM=1
# (CI), which makes that a failure.
# Usage: slurm_cluster_test.sh SUNGLINT SOURCE_DIR WORK_DIR
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
cluster=""
stop_cluster() {
  if [ -n "$cluster" ]; then
    bash "$src/scripts/slurm-local.sh" stop "$cluster" >>"$work/cluster.log" 2>&1
    cluster=""
  fi
}
trap stop_cluster EXIT
trap 'exit 1' INT TERM HUP
t_start=$(date +%s%N)
fails=0
fail() {
  echo "FAIL $*"
  fails=$((fails + 1))
}
ms() { echo $((($(date +%s%N) - t_start) / 1000000)); }

started=$(bash "$src/scripts/slurm-local.sh" start 2>"$work/cluster.log")
rc=$?
if [ $rc -ne 0 ]; then
  cat "$work/cluster.log"
  if [ $rc -eq 3 ] && [ "${SUNGLINT_REQUIRE_SLURM:-0}" != 1 ]; then
    echo "SKIP: Slurm (slurm-wlm, munge) is not installed; SUNGLINT_REQUIRE_SLURM=1 makes this a failure"
    exit 77
  fi
  echo "FAIL: the one-node cluster did not start (exit $rc)"
  exit 1
fi
eval "$started"
cluster=$(dirname "$SLURM_CONF")
echo "cluster up after $(ms) ms ($cluster)"

# wait_gone JOB SECONDS: until the job (all its array tasks) has left the queue.
wait_gone() {
  local n
  for n in $(seq $(($2 * 10))); do
    [ -z "$(squeue -h -j "$1" -o %i 2>/dev/null)" ] && return 0
    sleep 0.1
  done
  return 1
}
# A tiny study: 8 units (the reference's 2 batches of 2 frames, point and supersample).
study=("$src/scenes/simple.json" -m point -m "supersample --samples 2x2x1" --frames 0-1
  --width 32 --height 18 --reference 2x2x1 --budgets none --no-video -q)

cd "$work" || exit 1
"$bin" compare "${study[@]}" --out local >local.log 2>&1 || fail "local run: $(cat local.log)"
echo "local run done after $(ms) ms"

# 1. Submitted with tasks 1 and 3 killed in the middle of their unit.
SUNGLINT_TEST_KILL_TASKS=1,3 "$bin" compare "${study[@]}" --out sharded --slurm --max-parallel 2 \
  >submit1.log 2>&1 || fail "submission: $(cat submit1.log)"
cat submit1.log
array=$(sed -n 's/^submitted job array \([0-9]*\) .* merge job \([0-9]*\) .*/\1/p' submit1.log)
merge=$(sed -n 's/^submitted job array \([0-9]*\) .* merge job \([0-9]*\) .*/\2/p' submit1.log)
grep -q "^8 units, 0 in the cache: 8 tasks" submit1.log || fail "first submission: not 8 tasks"
[ -n "$array" ] && [ -n "$merge" ] || { fail "no job ids in: $(cat submit1.log)"; exit 1; }
wait_gone "$array" 30 || fail "job array $array still queued after 30 s"
echo "first array done after $(ms) ms"
for k in 1 3; do
  [ -f sharded/slurm/1/killed-task-$k ] || fail "task $k was not killed"
  grep -q "task $k killed on purpose" sharded/slurm/1/task-"${array}"_$k.log ||
    fail "task $k's log does not say it was killed"
done
# The merge waits on tasks that failed: it never runs, and no report exists.
reason=$(squeue -h -j "$merge" -o "%T %r" 2>/dev/null)
case $reason in PENDING*Depend*) ;; *) fail "merge job $merge: '$reason', expected pending on its dependency" ;; esac
[ -e sharded/index.html ] && fail "a report was written before every task succeeded"
# Exactly the killed tasks' units are missing.
"$bin" compare "${study[@]}" --out sharded --plan >plan.log 2>&1
grep -q "^8 units, 6 in the cache; 2 to render in 2 tasks" plan.log || fail "plan after the kills: $(tail -1 plan.log)"
killed_units=$(grep -E '^ +[0-9]+ ' plan.log | sed 's/^ *[0-9]* *[0-9.e-]* *//' | sort)
want_units=$(python3 -c "
import json; p = json.load(open('sharded/slurm/1/plan.json'))
print('\n'.join(sorted(u['id'] for k in (1, 3) for u in p['tasks'][k]['units'])))")
[ "$killed_units" = "$want_units" ] || fail "missing units '$killed_units', expected the killed tasks' '$want_units'"
ls -l --time-style=+%s.%N sharded/cache | grep -v "^total" | sort >before.txt

# 2. The same command again: the stale merge job cancelled, only the 2 missing units
# resubmitted, then the merge.
"$bin" compare "${study[@]}" --out sharded --slurm --max-parallel 2 >submit2.log 2>&1 ||
  fail "resubmission: $(cat submit2.log)"
cat submit2.log
grep -q "cancelled merge job $merge" submit2.log || fail "the stale merge job was not cancelled"
grep -q "^8 units, 6 in the cache: 2 tasks" submit2.log || fail "resubmission: not the 2 missing units"
merge2=$(sed -n 's/^submitted job array \([0-9]*\) .* merge job \([0-9]*\) .*/\2/p' submit2.log)
[ -n "$merge2" ] || { fail "no merge job in: $(cat submit2.log)"; exit 1; }
wait_gone "$merge2" 40 || fail "merge job $merge2 still queued after 40 s"
echo "merge done after $(ms) ms"
[ -f sharded/index.html ] || fail "no report after the merge: $(cat sharded/slurm/2/merge-*.log)"
# Nothing rendered twice: every frame of before is the same file, untouched.
ls -l --time-style=+%s.%N sharded/cache | grep -v "^total" | sort >after.txt
missing=$(comm -23 before.txt after.txt)
[ -z "$missing" ] || fail "frames rendered again or lost: $missing"

# 3. The same as the local run: frames byte for byte, results.json's numbers.
n=0
for f in local/cache/*.exr; do
  cmp -s "$f" "sharded/cache/$(basename "$f")" || fail "frame $(basename "$f") differs"
  n=$((n + 1))
done
[ "$n" -eq 8 ] || fail "expected 8 cached frames, got $n"
[ "$(ls sharded/cache/*.exr | wc -l)" -eq 8 ] || fail "sharded cache: not 8 frames"
python3 "$src/tests/cli/same_results.py" local/results.json sharded/results.json ||
  fail "results.json differ"

# 4. render --slurm: the frames as an array, then only a missing one; equal to a local render.
frames=("$src/scenes/simple.json" -m point --frames 0-3 --width 32 --height 18 -q)
"$bin" render "${frames[@]}" -o local-frames/p_%04d.exr --mkdir >/dev/null 2>&1 || fail "local render"
"$bin" render "${frames[@]}" -o frames/p_%04d.exr --mkdir --slurm >render1.log 2>&1 ||
  fail "render --slurm: $(cat render1.log)"
id=$(sed -n 's/^submitted job array \([0-9]*\):.*/\1/p' render1.log)
wait_gone "$id" 30 || fail "render array $id still queued"
rm -f frames/p_0002.exr
"$bin" render "${frames[@]}" -o frames/p_%04d.exr --slurm >render2.log 2>&1
grep -q "submitted job array [0-9]*: 1 of frames 0-3" render2.log || fail "render resubmission: $(cat render2.log)"
id=$(sed -n 's/^submitted job array \([0-9]*\):.*/\1/p' render2.log)
wait_gone "$id" 30 || fail "render array $id still queued"
for f in 0 1 2 3; do
  cmp -s "local-frames/p_000$f.exr" "frames/p_000$f.exr" || fail "render --slurm: frame $f differs"
done
echo "render --slurm done after $(ms) ms"

stop_cluster
[ -d "$(dirname "$SLURM_CONF")" ] && fail "the cluster's folder was left behind"
echo "slurm_cluster_test: $(ms) ms in all"
if [ $fails -ne 0 ]; then
  echo "slurm_cluster_test: $fails failures"
  exit 1
fi
echo "slurm_cluster_test: all checks passed"
