#!/usr/bin/env bash
# Edit -> first frame latency and drag frame rates of the editor at 256^2 and 512^2 with the
# default sampler on the default scene (issue 14; scripts/editor_latency.js says what is timed).
# Binaries run interleaved (A B A B ...) so machine load hits both alike; each prints its lines.
#   bash scripts/editor_latency.sh [ROUNDS=2] [REPS=3] WAVELIT [WAVELIT ...]
#   e.g. bash scripts/editor_latency.sh 2 3 /tmp/before-wavelit build/release/editor/wavelit
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-2}; reps=${2:-3}; shift 2 || true
binaries=("$@")
[ ${#binaries[@]} -gt 0 ] || binaries=(build/release/editor/wavelit)
for round in $(seq "$rounds"); do
    for size in 256 512; do
        for wavelit in "${binaries[@]}"; do
            WAVELIT_LATENCY_REPS=$reps WAVELIT_LATENCY_SIZE=$size WAVELIT_LATENCY_TAG="$(basename "$wavelit")#$round" \
                QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen} \
                "$wavelit" --size ${size}x${size} --script scripts/editor_latency.js 2>&1 | grep "^js: latency" || true
        done
    done
done
