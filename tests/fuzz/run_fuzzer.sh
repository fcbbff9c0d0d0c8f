#!/usr/bin/env bash
# Runs one libFuzzer harness for a fixed time (generated run_<fuzzer>.sh scripts call this; ctest
# label `fuzz` and scripts/fuzz.sh use those).
# Usage: run_fuzzer.sh BINARY WORK_DIR FINDINGS_DIR DICT|- SECONDS [--fresh] [libFuzzer flags...] -- CORPUS_DIR...
# New inputs go to WORK_DIR (emptied first with --fresh), never into the checked-in corpus; a crash
# is written to FINDINGS_DIR and the run exits non-zero. The last lines give the executions.
set -u
bin=$1 work=$2 findings=$3 dict=$4 seconds=$5
shift 5
fresh=0
flags=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    if [ "$1" = "--fresh" ]; then fresh=1; else flags+=("$1"); fi
    shift
done
shift # --
[ "$fresh" -eq 1 ] && rm -rf "$work"
mkdir -p "$work" "$findings"
[ "$dict" != "-" ] && flags+=("-dict=$dict")
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:allocator_may_return_null=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# WAVELIT_FUZZ_REPLAY=1 (scripts/test.sh, CI): run every corpus input once and stop (-runs=0) — the
# checked-in findings stay fixed, and the result cannot depend on what a mutation happens to reach
# in a few seconds on a given machine (Assimp has open hangs a mutation may hit: FINDINGS.md).
budget=(-max_total_time="$seconds")
[ "${WAVELIT_FUZZ_REPLAY:-0}" = 1 ] && budget=(-runs=0)
# -seed=1: the short ctest runs mutate the same way each time. -timeout: one input may take 10 s.
# -rss_limit_mb: no input may make a loader hold more than 2.5 GiB. Leaks are not checked: Assimp and
# OpenEXR leak on some error paths, which we cannot fix.
"$bin" "${budget[@]}" -seed="${WAVELIT_FUZZ_SEED:-1}" -timeout=10 -rss_limit_mb=2560 \
    -print_final_stats=1 -artifact_prefix="$findings/" "${flags[@]}" "$work" "$@"
rc=$?
if [ $rc -ne 0 ]; then
    echo "run_fuzzer: $(basename "$bin") found a problem (exit $rc); input in $findings/:" >&2
    ls -t "$findings" | head -3 >&2
fi
exit $rc
