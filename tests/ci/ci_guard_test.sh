#!/usr/bin/env bash
# scripts/ci-guard.sh against logs written here: it passes a suite that ran its tests and a
# fuzz run that loaded its corpus and ran its time, and fails, naming what is missing, on a
# suite with a skipped test (a GL test without a context), a suite without GL tests, a
# failed or empty suite, a fuzzer without a corpus and a fuzzer cut short.
# Usage: ci_guard_test.sh SOURCE_DIR WORK_DIR
set -u
src=$1 work=$2
guard=$src/scripts/ci-guard.sh
rm -rf "$work" && mkdir -p "$work"
fails=0 passes=0

# check NAME WANT_RC PATTERN MODE LOG_TEXT
check() {
  local name=$1 want=$2 pattern=$3 mode=$4 text=$5
  printf '%s\n' "$text" >"$work/$name.log"
  local out rc
  out=$(bash "$guard" "$mode" "$work/$name.log" 2>&1)
  rc=$?
  if [ "$rc" -eq "$want" ] && grep -qF -- "$pattern" <<<"$out"; then
    passes=$((passes + 1))
  else
    echo "FAIL $name: rc=$rc (wanted $want), wanted '$pattern', got: $out"
    fails=$((fails + 1))
  fi
}

ok_suite='1/3 Test #1: Rng.Uniform ....   Passed    0.01 sec
2/3 Test #2: GlEngineTest.Matches ....   Passed    3.00 sec
3/3 Test #3: cli ....   Passed    9.00 sec

100% tests passed, 0 tests failed out of 3

Label Time Summary:
cli        =   9.00 sec*proc (1 test)
gl         =   3.00 sec*proc (1 test)
unit       =   0.01 sec*proc (1 test)

Total Test time (real) =  12.00 sec'
check suite-ok 0 "3 tests ran, none failed or skipped" suite "$ok_suite"

check suite-skipped 1 "GlEngineTest.Matches (Skipped)" suite "$ok_suite
The following tests did not run:
	  2 - GlEngineTest.Matches (Skipped)"

check suite-disabled-is-fine 0 "none failed or skipped" suite "$ok_suite
The following tests did not run:
	 4 - ExtremeScenes.EveryMethodIsFinite (Disabled)"

check suite-no-gl 1 "no GL-labelled test ran" suite "$(grep -v '^gl ' <<<"$ok_suite")"

check suite-failed 1 "1 tests failed" suite "$(sed 's/100% tests passed, 0 tests failed out of 3/67% tests passed, 1 tests failed out of 3/' <<<"$ok_suite")"

check suite-empty 1 "no CTest summary" suite "No tests were found!!!"

check suite-none 1 "ran no test" suite "100% tests passed, 0 tests failed out of 0"

ok_fuzz='INFO: Seed: 42
INFO: seed corpus: files: 118 min: 2b max: 9000b total: 100000b rss: 40Mb
#119	INITED cov: 900 ft: 2000 corp: 100/80Kb exec/s: 0 rss: 60Mb
Done 123456 runs in 61 second(s)'
check fuzz-ok 0 "loaded 118 seed files" fuzz "$ok_fuzz"
check fuzz-no-corpus 1 "loaded no seed corpus" fuzz "$(sed 's/files: 118/files: 0/' <<<"$ok_fuzz")"
check fuzz-no-corpus-line 1 "loaded no seed corpus" fuzz "$(grep -v 'seed corpus' <<<"$ok_fuzz")"
check fuzz-short 1 "ran 3 s of 60" fuzz "$(sed 's/in 61 second/in 3 second/' <<<"$ok_fuzz")"
check fuzz-unfinished 1 "did not finish" fuzz "$(grep -v '^Done' <<<"$ok_fuzz")"

out=$(bash "$guard" suite "$work/missing-log.log" 2>&1)
if [ $? -eq 1 ] && grep -qF "no log at" <<<"$out"; then passes=$((passes + 1)); else
  echo "FAIL missing log: $out"
  fails=$((fails + 1))
fi
out=$(bash "$guard" frobnicate "$work/suite-ok.log" 2>&1)
if [ $? -eq 2 ] && grep -qF "usage" <<<"$out"; then passes=$((passes + 1)); else
  echo "FAIL usage: $out"
  fails=$((fails + 1))
fi

echo "ci_guard: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
