#!/usr/bin/env bash
# README command 2: install what is missing, build, and run every test through ctest.
# Tests render through real Vulkan on lavapipe with validation layers on, and drive the real Qt
# editor on the offscreen platform. Pass extra ctest arguments through, e.g. `-L fast`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh release
export WAVELIT_VK_VALIDATION=1
export QT_QPA_PLATFORM=offscreen
ctest --preset release -j2 "$@"
# The loaders' libFuzzer harnesses (tests/fuzz/README.md), clang + ASan/UBSan in build/fuzz: here
# every checked-in corpus input (seeds and every past finding) runs once, a deterministic regression
# check; `ctest --preset fuzz` mutates for a few seconds each and scripts/fuzz.sh for longer.
# WAVELIT_SKIP_FUZZ=1 skips them.
if [ "${WAVELIT_SKIP_FUZZ:-0}" != 1 ]; then
    bash scripts/build.sh fuzz
    WAVELIT_FUZZ_REPLAY=1 ctest --preset fuzz -j2
fi
