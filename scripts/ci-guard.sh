#!/usr/bin/env bash
# CI's guard against a stage that passes by doing nothing (.ci/run, docs/ci.md).
#
#   ci-guard.sh suite LOG   a CTest log: some tests ran, every one passed, none was skipped
#                           (a GL test without a context, a window test without a display),
#                           and the GL-labelled tests were among them
#   ci-guard.sh fuzz LOG    a libFuzzer log: the seed corpus was found and loaded (some
#                           files) and the run lasted its time (FUZZ_SECONDS, default 60)
#
# Exits 0 when the log shows the work done, 1 naming what is missing, 2 on a usage error.
set -uo pipefail

fail() {
  echo "ci-guard: $*" >&2
  exit 1
}

[ $# -eq 2 ] || {
  echo "usage: ci-guard.sh suite|fuzz LOG" >&2
  exit 2
}
mode=$1 log=$2
[ -r "$log" ] || fail "no log at '$log'"

case $mode in
  suite)
    summary=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' "$log" | tail -n 1)
    [ -n "$summary" ] || fail "$log: no CTest summary (did the suite run?)"
    ran=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$summary")
    failed=$(sed -E 's/.*, ([0-9]+) tests failed.*/\1/' <<<"$summary")
    [ "$ran" -gt 0 ] || fail "$log: the suite ran no test"
    [ "$failed" -eq 0 ] || fail "$log: $failed tests failed"
    skipped=$(grep -E '\((Skipped)\)$' "$log" | sed -E 's/^[[:space:]]+//')
    [ -z "$skipped" ] || fail "$log: tests were skipped (a stage that must run did not):
$skipped"
    gl=$(grep -E '^gl +=' "$log" | tail -n 1)
    [ -n "$gl" ] || fail "$log: no GL-labelled test ran (the GL engine went untested)"
    echo "ci-guard: $ran tests ran, none failed or skipped; $gl"
    ;;
  fuzz)
    want=${FUZZ_SECONDS:-60}
    seeds=$(grep -oE 'INFO: seed corpus: files: [0-9]+' "$log" | grep -oE '[0-9]+$' | tail -n 1)
    [ -n "$seeds" ] && [ "$seeds" -gt 0 ] || fail "$log: the fuzzer loaded no seed corpus"
    done_line=$(grep -E '^Done [0-9]+ runs in [0-9]+ second' "$log" | tail -n 1)
    [ -n "$done_line" ] || fail "$log: the fuzzer did not finish its run"
    secs=$(sed -E 's/^Done [0-9]+ runs in ([0-9]+) second.*/\1/' <<<"$done_line")
    [ "$secs" -ge $((want - 1)) ] || fail "$log: the fuzzer ran ${secs} s of ${want}"
    echo "ci-guard: fuzzer loaded $seeds seed files; $done_line"
    ;;
  *)
    echo "usage: ci-guard.sh suite|fuzz LOG" >&2
    exit 2
    ;;
esac
