#!/usr/bin/env bash
# Makes the README's editor screenshots (docs/img/editor_*.png) with the real editor on the
# offscreen platform (no display needed): scripts/editor_screenshots.js drives it.
#   bash scripts/editor_screenshots.sh [WAVELIT]   (default: build/release's editor)
set -euo pipefail
cd "$(dirname "$0")/.."
wavelit=${1:-build/release/editor/wavelit}
mkdir -p docs/img
WAVELIT_SCRIPT_OUT=$(pwd)/docs/img QT_QPA_PLATFORM=offscreen "$wavelit" \
    resources/scenes/ring_on_ground.wlscene --script scripts/editor_screenshots.js --size 320x240
echo "editor_screenshots: wrote docs/img/editor_selected.png and docs/img/editor_dragged.png"
