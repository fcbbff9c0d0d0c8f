#!/usr/bin/env bash
# The shadow-field drag's A/B of docs/relighting.md §7.0e: the ring (ring_on_ground) and small_box
# (cornell_box) translation drags, BEFORE_CLI with today's exact drag, AFTER_CLI with
# --shadow-field --field-check, A B A B RUNS times at PREVIEW^2 (default 256) on 2 threads; prints
# the median incrementalCpuMs / incrementalMs per scene and binary and the field's relRMSE against
# the exact preview per step.
#   bash scripts/relight_field_ab.sh BEFORE_CLI AFTER_CLI [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
before=$1 after=$2 runs=${3:-2} preview=${PREVIEW:-256}
out=out/relight-field-ab
mkdir -p "$out"
cat > "$out/ring.json" <<'JSON'
[{"entity": "object:ring", "property": "translation", "value": [0.3, 0.12, 0.0]},
 {"entity": "object:ring", "property": "translation", "value": [0.35, 0.12, 0.05]},
 {"entity": "object:ring", "property": "translation", "value": [0.4, 0.12, 0.05]},
 {"entity": "object:ring", "property": "translation", "value": [0.45, 0.12, 0.1]}]
JSON
cat > "$out/cornell.json" <<'JSON'
[{"entity": "object:small_box", "property": "translation", "value": [0.3, 0.3, 0.25]},
 {"entity": "object:small_box", "property": "translation", "value": [0.25, 0.3, 0.2]},
 {"entity": "object:small_box", "property": "translation", "value": [0.2, 0.3, 0.15]},
 {"entity": "object:small_box", "property": "translation", "value": [0.15, 0.3, 0.1]}]
JSON
for r in $(seq "$runs"); do
    for s in ring cornell; do
        scene=ring_on_ground
        [[ $s == cornell ]] && scene=cornell_box
        for v in before after; do
            cli=$before extra=()
            [[ $v == after ]] && cli=$after extra=(--shadow-field --field-check)
            echo "relight field A/B: $s $v run $r"
            "$cli" relight "resources/scenes/$scene.wlscene" --edits "$out/$s.json" --out "$out/$s-$v" \
                --report "$out/$s-$v-$r.json" --preview "$preview" --width "$preview" --height "$preview" \
                --threads 2 --skip-full-rebuild "${extra[@]}" >/dev/null
        done
    done
done
python3 - "$out" "$runs" <<'PY'
import json, statistics, sys
out, runs = sys.argv[1], int(sys.argv[2])
for s in ("ring", "cornell"):
    for v in ("before", "after"):
        cpu, wall, rel = [], [], []
        for r in range(1, runs + 1):
            for e in json.load(open(f"{out}/{s}-{v}-{r}.json"))["edits"]:
                cpu.append(e["incrementalCpuMs"]); wall.append(e["incrementalMs"])
                if "fieldVsExactRelRMSE" in e and r == 1: rel.append(round(e["fieldVsExactRelRMSE"], 4))
        print(f"{s} {v}: CPU ms median {statistics.median(cpu):.0f} ({min(cpu):.0f}-{max(cpu):.0f}), "
              f"wall ms median {statistics.median(wall):.0f}, n {len(cpu)}" + (f", field vs exact {rel}" if rel else ""))
PY
