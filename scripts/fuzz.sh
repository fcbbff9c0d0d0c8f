#!/usr/bin/env bash
# Builds the libFuzzer harnesses (CMake preset `fuzz`: clang, ASan + UBSan) and runs each for
# SECONDS (default 600) at low priority, one after another: longer runs than ctest's label `fuzz`.
# New inputs accumulate in build/fuzz/tests/fuzz/work/<fuzzer>/ across runs; a crash stops that
# fuzzer, lands in build/fuzz/tests/fuzz/findings/<fuzzer>/ and makes the script exit 1 (turn it into
# a corpus file, a regression test and a fix: tests/fuzz/README.md). Each run's log is in
# build/fuzz/logs/, and one line per run (executions, corpus size, result) is appended to
# build/fuzz/fuzz-summary.txt.
# Usage: bash scripts/fuzz.sh [SECONDS] [FUZZER...]   e.g. bash scripts/fuzz.sh 60 fuzz_hdr fuzz_exr
# Extra libFuzzer flags, e.g. to keep going after a finding and collect them all:
#   WAVELIT_FUZZ_FLAGS="-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1" bash scripts/fuzz.sh
# Each run takes a random seed; WAVELIT_FUZZ_SEED=N repeats one (ctest's short runs use 1).
set -uo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
fuzzers=("$@")
if [ ${#fuzzers[@]} -eq 0 ]; then
    fuzzers=(fuzz_scene fuzz_lighting fuzz_exr fuzz_hdr fuzz_obj fuzz_gltf fuzz_ply)
fi
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (scripts/install-deps.sh installs clang)" >&2; exit 2; }
cmake --preset fuzz >/dev/null || exit 2
cmake --build --preset fuzz -j"$(nproc)" || exit 2

mkdir -p build/fuzz/logs
export WAVELIT_FUZZ_SEED=${WAVELIT_FUZZ_SEED:-0}
status=0
for f in "${fuzzers[@]}"; do
    runner=build/fuzz/tests/fuzz/run_$f.sh
    [ -f "$runner" ] || { echo "fuzz.sh: no fuzzer '$f'" >&2; status=2; continue; }
    log=build/fuzz/logs/$f-$(date -u +%Y%m%dT%H%M%S).log
    echo "fuzz.sh: $f for ${seconds}s (log $log)"
    findings=build/fuzz/tests/fuzz/findings/$f
    before=$(find "$findings" -type f 2>/dev/null | wc -l)
    # shellcheck disable=SC2086
    nice -n 10 bash "$runner" "$seconds" ${WAVELIT_FUZZ_FLAGS:-} >"$log" 2>&1
    rc=$?
    # Executions: libFuzzer's final stats, or in -fork mode the count on its last status line.
    execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{s += $2} END {print s + 0}')
    [ "$execs" -eq 0 ] && execs=$(grep -aoE '^#[0-9]+' "$log" | tail -1 | tr -d '#')
    corpus=$(find "build/fuzz/tests/fuzz/work/$f" -type f | wc -l)
    new=$(( $(find "$findings" -type f 2>/dev/null | wc -l) - before ))
    result=ok
    if [ $rc -ne 0 ] || [ "$new" -gt 0 ]; then
        result="FINDING (exit $rc, $new new in $findings): $(grep -a -m1 -E 'ERROR: |fuzz finding:|runtime error:' "$log")"
        status=1
    fi
    line="$(date -u +%FT%TZ) $f ${seconds}s execs=$execs work_corpus=$corpus $result"
    echo "$line" | tee -a build/fuzz/fuzz-summary.txt
done
exit $status
