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
