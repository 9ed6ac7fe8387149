#!/usr/bin/env bash
# The study as tasks from the command line (docs/cluster.md), without a cluster: --plan,
# every --task, then --merge give the local run's frames byte for byte and its results.json
# numbers; the plan's refusals; and --slurm against stand-in Slurm commands on PATH: a
# missing sbatch, a Slurm error and folders the nodes cannot see, each reported with the
# command and its message (exit 1); the batch scripts it writes against golden files
# (tests/golden/slurm-array.sh, slurm-merge.sh).
# Usage: tasks_test.sh SUNGLINT SOURCE_DIR WORK_DIR
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
cd "$work" || exit 1
fails=0 passes=0
ok() { passes=$((passes + 1)); }
fail() {
  echo "FAIL $*"
  fails=$((fails + 1))
}
# expect_rc NAME RC PATTERN CMD...: the command must exit with RC and print PATTERN.
expect_rc() {
  local name=$1 want=$2 pattern=$3
  shift 3
  local out rc
  out=$("$@" 2>&1)
  rc=$?
  if [ $rc -eq "$want" ] && grep -qF -- "$pattern" <<<"$out"; then ok; else
    fail "$name: rc=$rc (wanted $want), wanted '$pattern', got: $out"
  fi
}

# 11 units: the reference's 2 batches of 2 frames, point, taa's range (one unit, 2 frames),
# supersample 2x2x1 and the budget 1x1x1 per frame; 12 frames.
study=("$src/scenes/simple.json" -m point -m taa -m "supersample --samples 2x2x1" --frames 0-1
  --width 32 --height 18 --reference 2x2x1 --budgets 1x1x1 --no-video -q)
one_frame=("$src/scenes/simple.json" -m point --frames 0-0 --width 32 --height 18
  --reference 2x2x1 --budgets 1x1x1 --no-video -q)

# 1. Local, and as tasks: the same frames and numbers.
"$bin" compare "${study[@]}" --out local >/dev/null 2>&1 || fail "local run"
"$bin" compare "${study[@]}" --out sharded --plan >plan.log 2>&1 || fail "plan: $(cat plan.log)"
grep -q "^11 units, 0 in the cache; 11 to render in 11 tasks: estimated" plan.log ||
  fail "plan: $(tail -2 plan.log)"
grep -q "simple: taa, frames 0-1 (stateful)" plan.log || fail "plan: taa's range is not one unit"
grep -q "simple: reference --samples 2x2x1, frame 1, batch 2/2" plan.log || fail "plan: no reference batch unit"
for k in 10 3 0 7 1 2 4 5 6 8 9 3; do  # any order; task 3 twice renders nothing twice
  "$bin" compare "${study[@]}" --out sharded --task $k >task.log 2>&1 || fail "task $k: $(cat task.log)"
done
grep -q "^task 3: 0 units rendered, 1 already in the cache" task.log || fail "task 3 again: $(cat task.log)"
expect_rc "plan of a complete cache" 0 "11 units, 11 in the cache; 0 to render in 0 tasks" \
  "$bin" compare "${study[@]}" --out sharded --plan
"$bin" compare "${study[@]}" --out sharded --merge >/dev/null 2>&1 || fail "merge"
n=0
for f in local/cache/*.exr; do
  cmp -s "$f" "sharded/cache/$(basename "$f")" || fail "frame $(basename "$f") differs"
  n=$((n + 1))
done
[ "$n" -eq 12 ] || fail "expected 12 cached frames, got $n"
python3 "$src/tests/cli/same_results.py" local/results.json sharded/results.json && ok ||
  fail "results.json differ"

# 2. The plan's refusals.
"$bin" compare "${study[@]}" --out other --plan >/dev/null 2>&1
expect_rc "task past the plan" 2 "--task: 11 is not a task of other/plan.json (0 to 10)" \
  "$bin" compare "${study[@]}" --out other --task 11
expect_rc "task of another study" 1 "is the plan of another study" \
  "$bin" compare "${one_frame[@]}" --out other --task 0
expect_rc "task without a plan" 1 "--task: no plan 'none/plan.json'" \
  "$bin" compare "${study[@]}" --out none --task 0
expect_rc "merge of an incomplete cache" 1 "--merge: 11 of the study's units are not in the cache" \
  "$bin" compare "${study[@]}" --out other --merge
expect_rc "two modes" 2 "--plan, --task, --merge and --slurm: give one of them" \
  "$bin" compare "${study[@]}" --out other --plan --slurm
expect_rc "bad time" 2 "--time-per-task: expected Slurm's time format" \
  "$bin" compare "${study[@]}" --out other --slurm --time-per-task 1h

# 3. --slurm against stand-in commands (fake/): they log their arguments and print job ids.
mkdir -p fake empty
cat >fake/sinfo <<'EOF'
#!/bin/bash
if [ -n "${FAKE_SINFO_FAIL:-}" ]; then echo "sinfo: error: invalid partition specified: $3 $4 $5 $6" >&2; exit 1; fi
for n in ${FAKE_NODES:-$(hostname -s)}; do echo "$n"; done
EOF
cat >fake/sbatch <<'EOF'
#!/bin/bash
echo "$*" >>"$FAKE_LOG/sbatch.args"
if [ -n "${FAKE_SBATCH_FAIL:-}" ]; then
  echo "sbatch: error: Batch job submission failed: Invalid partition name specified" >&2; exit 1
fi
n=$(($(cat "$FAKE_LOG/id" 2>/dev/null || echo 4000) + 1)); echo $n >"$FAKE_LOG/id"; echo "$n"
EOF
printf '#!/bin/bash\necho "MaxArraySize            = 1001"\n' >fake/scontrol
printf '#!/bin/bash\nexit 0\n' >fake/squeue
printf '#!/bin/bash\necho "$*" >>"$FAKE_LOG/scancel.args"\n' >fake/scancel
chmod +x fake/*
export FAKE_LOG=$work/fake
slurm=("${study[@]}" --slurm --partition short --max-parallel 3 --time-per-task 0:10:00 --requeue)
expect_rc "missing sbatch" 1 "--slurm: sbatch: not found on PATH" \
  env PATH="$work/empty" "$bin" compare "${slurm[@]}" --out s0
expect_rc "sinfo error" 1 "--slurm: \`sinfo -h -N -o %N -p short\` failed (exit 1): sinfo: error: invalid partition" \
  env PATH="$work/fake:$PATH" FAKE_SINFO_FAIL=1 "$bin" compare "${slurm[@]}" --out s1
expect_rc "sbatch error" 1 "failed (exit 1): sbatch: error: Batch job submission failed: Invalid partition name specified" \
  env PATH="$work/fake:$PATH" FAKE_SBATCH_FAIL=1 "$bin" compare "${slurm[@]}" --out s2
grep -q "^--parsable $work/s2/slurm/1/array.sh" fake/sbatch.args || fail "sbatch's command: $(cat fake/sbatch.args)"
type=$(stat -f -c %T "$work")
case $type in
  nfs* | lustre | gpfs | ceph* | fuse*) echo "  (not-shared check skipped: $work is on $type)" ;;
  *)
    expect_rc "folders the nodes do not see" 1 "is on a local filesystem" \
      env PATH="$work/fake:$PATH" FAKE_NODES="node1 node2" "$bin" compare "${slurm[@]}" --out s3
    expect_rc "--assume-shared" 0 "submitted job array" \
      env PATH="$work/fake:$PATH" FAKE_NODES="node1 node2" "$bin" compare "${slurm[@]}" --out s3 --assume-shared
    ;;
esac
rm -f fake/id
expect_rc "submission" 0 "submitted job array 4001 (11 tasks, at most 3 at once) and merge job 4002" \
  env PATH="$work/fake:$PATH" "$bin" compare "${slurm[@]}" --out s4
grep -q "^--parsable --dependency=afterok:4001 $work/s4/slurm/1/merge.sh" fake/sbatch.args ||
  fail "merge's sbatch: $(tail -1 fake/sbatch.args)"
# The scripts against the golden files, with this run's folders named.
for s in array merge; do
  sed -e "s|$bin|@SUNGLINT@|g" -e "s|$work|@WORK@|g" -e "s|$src|@SRC@|g" \
    "s4/slurm/1/$s.sh" >"$s.sh"
  if diff -u "$src/tests/golden/slurm-$s.sh" "$s.sh" >"$s.diff"; then ok; else
    fail "s4/slurm/1/$s.sh differs from tests/golden/slurm-$s.sh: $(cat "$s.diff")"
  fi
done
bash -n s4/slurm/1/array.sh && bash -n s4/slurm/1/merge.sh && ok || fail "the scripts are not valid bash"

echo "tasks_test: $passes passed, $fails failed"
[ $fails -eq 0 ]
