#!/usr/bin/env bash
# The shadow-field drag's A/B of docs/relighting.md §7.0e: the ring (ring_on_ground) and small_box
# (cornell_box) translation drags, BEFORE_CLI with today's exact drag, AFTER_CLI with
# --shadow-field --field-check, A B A B RUNS times at PREVIEW^2 (default 256) on 2 threads; prints
# the median incrementalCpuMs / incrementalMs per scene and binary and the field's relRMSE against
# the exact preview per step. BEFORE_ARGS="--shadow-field" compares two field drags; AFTER_EXTRA
# adds flags to the after runs (--field-carry-own, docs/relighting.md §7.0j).
#   bash scripts/relight_field_ab.sh BEFORE_CLI AFTER_CLI [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/relight-field-ab
mkdir -p "$out"
cat > "$out/ring_on_ground.edits.json" <<'JSON'
[{"entity": "object:ring", "property": "translation", "value": [0.3, 0.12, 0.0]},
 {"entity": "object:ring", "property": "translation", "value": [0.35, 0.12, 0.05]},
 {"entity": "object:ring", "property": "translation", "value": [0.4, 0.12, 0.05]},
 {"entity": "object:ring", "property": "translation", "value": [0.45, 0.12, 0.1]}]
JSON
cat > "$out/cornell_box.edits.json" <<'JSON'
[{"entity": "object:small_box", "property": "translation", "value": [0.3, 0.3, 0.25]},
 {"entity": "object:small_box", "property": "translation", "value": [0.25, 0.3, 0.2]},
 {"entity": "object:small_box", "property": "translation", "value": [0.2, 0.3, 0.15]},
 {"entity": "object:small_box", "property": "translation", "value": [0.15, 0.3, 0.1]}]
JSON
SCENES="ring_on_ground cornell_box" LISTS=$out AFTER_ARGS="--shadow-field --field-check ${AFTER_EXTRA:-}" \
    exec bash scripts/relight_bench.sh --ab "$1" "$2" "${3:-2}"
