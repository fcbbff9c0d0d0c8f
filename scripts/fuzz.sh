#!/usr/bin/env bash
# Builds the libFuzzer harnesses (CMake preset `fuzz`: clang, ASan + UBSan) and runs each for
# SECONDS (default 600) at low priority, one after another: longer runs than ctest's label `fuzz`.
# New inputs accumulate in build/fuzz/tests/fuzz/work/<fuzzer>/ across runs; a crash stops that
# fuzzer, lands in build/fuzz/tests/fuzz/findings/<fuzzer>/ and makes the script exit 1 (turn it into
# a corpus file, a regression test and a fix: tests/fuzz/README.md). Each run's log is in
# build/fuzz/logs/, and one line per run (executions, corpus size, result) is appended to
# build/fuzz/fuzz-summary.txt.
# Usage: bash scripts/fuzz.sh [SECONDS] [FUZZER...]   e.g. bash scripts/fuzz.sh 60 fuzz_hdr fuzz_exr
# Extra libFuzzer flags: WAVELIT_FUZZ_FLAGS="-jobs=2 -workers=2" bash scripts/fuzz.sh
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
status=0
for f in "${fuzzers[@]}"; do
    runner=build/fuzz/tests/fuzz/run_$f.sh
    [ -f "$runner" ] || { echo "fuzz.sh: no fuzzer '$f'" >&2; status=2; continue; }
    log=build/fuzz/logs/$f-$(date -u +%Y%m%dT%H%M%S).log
    echo "fuzz.sh: $f for ${seconds}s (log $log)"
    # shellcheck disable=SC2086
    nice -n 10 bash "$runner" "$seconds" ${WAVELIT_FUZZ_FLAGS:-} >"$log" 2>&1
    rc=$?
    execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{s += $2} END {print s + 0}')
    corpus=$(find "build/fuzz/tests/fuzz/work/$f" -type f | wc -l)
    result=ok
    if [ $rc -ne 0 ]; then
        result="FINDING (exit $rc): $(grep -m1 -E 'ERROR: |fuzz finding:|runtime error:' "$log")"
        status=1
    fi
    line="$(date -u +%FT%TZ) $f ${seconds}s execs=$execs work_corpus=$corpus $result"
    echo "$line" | tee -a build/fuzz/fuzz-summary.txt
done
exit $status
