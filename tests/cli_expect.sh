#!/usr/bin/env bash
# Shared by the CLI tests that check exit codes and messages (sourced, not a test itself):
# sets cli, src, tmp (removed on exit) and failures from the test's arguments
# (<wavelit-cli> <source-dir>), and defines
#   fail MESSAGE...                 count a failure and print it;
#   expect CODE NEEDLE... -- ARGS...  run the CLI, check its exit code and that stderr holds every
#                                   NEEDLE. CLI_TIMEOUT (seconds, optional) bounds each run.
cli="$1"
src="$2"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

expect() {
    local code="$1"
    shift
    local needles=()
    while [ "$1" != "--" ]; do needles+=("$1"); shift; done
    shift
    local runner=()
    [ -n "${CLI_TIMEOUT:-}" ] && runner=(timeout "$CLI_TIMEOUT")
    "${runner[@]}" "$cli" "$@" >"$tmp/out" 2>"$tmp/err"
    local rc=$?
    [ "$rc" -eq "$code" ] || fail "'$*' exited $rc, expected $code: $(cat "$tmp/err")"
    for n in "${needles[@]}"; do
        grep -qF -- "$n" "$tmp/err" || fail "'$*' did not print '$n': $(cat "$tmp/err")"
    done
}
