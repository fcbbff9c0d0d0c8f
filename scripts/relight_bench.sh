#!/usr/bin/env bash
# The figures of docs/relighting.md: `wavelit-cli relight` on the bundled scenes.
#  1. latency: every edit kind at a 256^2 preview on 2 threads, incremental vs from scratch;
#  2. preview resolution: relRMSE of 128^2 output from 128^2 / 64^2 / 32^2 preview points against
#     a converged direct-lighting reference (CPU tracer, bounces 1, REF_SPP spp);
#  3. coefficient budget: relRMSE vs K on the same reference.
# Latency runs also take the coarse-to-fine first answer (--coarse-level 3: the 8^2 grid) and
# report its cost next to the full one's; the quality runs report its relRMSE (coarseRelRMSE).
# Timings vary with the machine and its load (the report says so); run it on a quiet machine.
#   bash scripts/relight_bench.sh [CLI] [REF_SPP]   (defaults: build/release/renderer/cli/wavelit-cli, 512)
#   bash scripts/relight_bench.sh --ab BEFORE_CLI AFTER_CLI [RUNS]
#     the drag lists of docs/relighting.md §7.0a (four light positions, two roughness values, two
#     object moves per scene; glossy_sphere at --level 6), run A B A B ... RUNS times (default 2),
#     and the median incrementalCpuMs / incrementalMs per edit kind and binary. PREVIEW=N (default
#     256) sets the preview and output size. FIRST=1 also takes the coarse-to-fine first answer
#     (--coarse-level 3 --coarse-stride 2) in both binaries and prints a second table: the after
#     binary's corrected first answer (firstCpuMs, firstMs, its relRMSE against the exact preview)
#     next to the before binary's coarse answer (coarseMs) and full update. SCENES="a b" runs a
#     subset; LISTS=DIR takes DIR/SCENE.edits.json instead of the lists below; AFTER_ARGS adds
#     flags to the after binary's runs (a report's fieldVsExactRelRMSE is then listed per step),
#     BEFORE_ARGS to the before binary's.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ "${1:-}" == --ab ]]; then
    before=$2 after=$3 runs=${4:-2} preview=${PREVIEW:-256}
    first=()
    [[ ${FIRST:-0} == 1 ]] && first=(--coarse-level 3 --coarse-stride 2)
    out=out/relight-ab
    scenes=(${SCENES:-ring_on_ground cornell_box glossy_sphere})
    afterArgs=(${AFTER_ARGS:-})
    beforeArgs=(${BEFORE_ARGS:-})
    mkdir -p "$out"
    cat > "$out/ring_on_ground.edits.json" <<'JSON'
[{"entity": "environment", "property": "rotation", "value": 90},
 {"entity": "light:softbox", "property": "position", "value": [0.5, 3.0, 2.0]},
 {"entity": "light:softbox", "property": "position", "value": [0.7, 3.0, 1.8]},
 {"entity": "light:softbox", "property": "position", "value": [0.9, 2.9, 1.6]},
 {"entity": "light:softbox", "property": "position", "value": [1.1, 2.8, 1.4]},
 {"entity": "material:gold", "property": "roughness", "value": 0.4},
 {"entity": "material:gold", "property": "roughness", "value": 0.3},
 {"entity": "object:ring", "property": "translation", "value": [0.3, 0.12, 0.0]},
 {"entity": "object:ring", "property": "translation", "value": [0.35, 0.12, 0.05]}]
JSON
    cat > "$out/cornell_box.edits.json" <<'JSON'
[{"entity": "light:ceiling_light", "property": "position", "value": [0.1, 1.98, 0.0]},
 {"entity": "light:ceiling_light", "property": "position", "value": [0.15, 1.98, 0.05]},
 {"entity": "light:ceiling_light", "property": "position", "value": [0.2, 1.98, 0.1]},
 {"entity": "light:ceiling_light", "property": "position", "value": [0.0, 1.98, 0.0]},
 {"entity": "material:blue_box", "property": "roughness", "value": 0.5},
 {"entity": "material:blue_box", "property": "roughness", "value": 0.4},
 {"entity": "object:small_box", "property": "translation", "value": [0.2, 0.0, 0.1]},
 {"entity": "object:small_box", "property": "translation", "value": [0.25, 0.0, 0.1]}]
JSON
    cat > "$out/glossy_sphere.edits.json" <<'JSON'
[{"entity": "environment", "property": "rotation", "value": 120},
 {"entity": "light:sun", "property": "direction", "value": [0.3, -0.8, -0.5]},
 {"entity": "light:sun", "property": "direction", "value": [0.35, -0.8, -0.45]},
 {"entity": "material:chrome", "property": "roughness", "value": 0.25},
 {"entity": "material:chrome", "property": "roughness", "value": 0.2}]
JSON
    [[ -n ${LISTS:-} ]] && for s in "${scenes[@]}"; do cp "$LISTS/$s.edits.json" "$out/"; done
    for s in "${scenes[@]}"; do
        level=auto
        [[ $s == glossy_sphere ]] && level=6
        for r in $(seq "$runs"); do
            for v in before after; do
                cli=$before extra=("${beforeArgs[@]}")
                [[ $v == after ]] && cli=$after extra=("${afterArgs[@]}")
                echo "relight bench --ab: $s $v run $r"
                "$cli" relight "resources/scenes/$s.wlscene" --edits "$out/$s.edits.json" --out "$out/$s-$v" \
                    --report "$out/$s-$v-$r.json" --preview "$preview" --width "$preview" --height "$preview" \
                    --threads 2 --level "$level" --skip-full-rebuild "${first[@]}" "${extra[@]}" >/dev/null
            done
        done
    done
    python3 - "$out" "$runs" "${scenes[@]}" <<'PY'
import json, statistics, sys
out, runs, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
print("| scene | edit | points touched | before CPU ms (n) | after CPU ms (n) | after / before | before -> after wall ms |")
print("|---|---|---|---|---|---|---|")
vsExact = []
for s in scenes:
    rows = {}
    for v in ("before", "after"):
        for r in range(1, runs + 1):
            for e in json.load(open(f"{out}/{s}-{v}-{r}.json"))["edits"]:
                key = f"{e['entity']} {e['property']}"
                rows.setdefault(key, {"before": [], "after": [], "points": e["pointsTouched"], "vsExact": []})[v].append(
                    (e["incrementalCpuMs"], e["incrementalMs"]))
                if v == "after" and r == 1 and "fieldVsExactRelRMSE" in e:
                    rows[key]["vsExact"].append(round(e["fieldVsExactRelRMSE"], 4))
    for key, d in rows.items():
        cpu = {v: statistics.median(c for c, _ in d[v]) for v in ("before", "after")}
        wall = {v: statistics.median(w for _, w in d[v]) for v in ("before", "after")}
        print(f"| {s} | {key} | {d['points']} | {cpu['before']:.1f} ({len(d['before'])}) | {cpu['after']:.1f} "
              f"({len(d['after'])}) | {cpu['after'] / max(cpu['before'], 1e-3):.2f} | {wall['before']:.0f} -> {wall['after']:.0f} |")
        if d["vsExact"]: vsExact.append(f"{s} {key}: relRMSE against the exact preview per step (run 1) {d['vsExact']}")
for line in vsExact: print(line)
first = {}
for s in scenes:
    for r in range(1, runs + 1):
        for e in json.load(open(f"{out}/{s}-after-{r}.json"))["edits"]:
            if "firstCpuMs" in e:
                first.setdefault((s, f"{e['entity']} {e['property']}"), []).append(e)
        for e in json.load(open(f"{out}/{s}-before-{r}.json"))["edits"]:
            if "coarseMs" in e:
                first.setdefault((s, f"{e['entity']} {e['property']}"), []).append(dict(beforeCoarseMs=e["coarseMs"]))
if first:
    print()
    print("| scene | edit | full update CPU ms (after) | first answer CPU ms | first answer wall ms | before: coarse answer wall ms | relRMSE vs exact preview: first answer | coarse image |")
    print("|---|---|---|---|---|---|---|---|")
    med = lambda es, k: statistics.median(e[k] for e in es if k in e)
    for (s, key), es in first.items():
        print(f"| {s} | {key} | {med(es, 'incrementalCpuMs'):.0f} | {med(es, 'firstCpuMs'):.1f} | {med(es, 'firstMs'):.1f} | "
              f"{med(es, 'beforeCoarseMs'):.1f} | {med(es, 'firstVsPreviewRelRMSE'):.3f} | {med(es, 'coarseVsPreviewRelRMSE'):.3f} |")
PY
    uptime
    exit 0
fi
cli=${1:-build/release/renderer/cli/wavelit-cli}
spp=${2:-512}
out=out/relight
mkdir -p "$out"
edits() { # scene name -> an edits file with every edit kind that scene has
    case "$1" in
    ring_on_ground) cat <<'JSON'
[{"entity": "environment", "property": "rotation", "value": 90},
 {"entity": "environment", "property": "intensity", "value": 1.5},
 {"entity": "light:softbox", "property": "position", "value": [0.5, 3.0, 2.0]},
 {"entity": "light:softbox", "property": "intensity", "value": 90},
 {"entity": "material:ground", "property": "baseColor", "value": [0.3, 0.5, 0.7]},
 {"entity": "material:gold", "property": "baseColor", "value": [0.9, 0.6, 0.3]},
 {"entity": "material:gold", "property": "roughness", "value": 0.4},
 {"entity": "object:ring", "property": "translation", "value": [0.3, 0.12, 0.0]}]
JSON
    ;;
    glossy_sphere) cat <<'JSON'
[{"entity": "environment", "property": "rotation", "value": 120},
 {"entity": "light:sun", "property": "direction", "value": [0.3, -0.8, -0.5]},
 {"entity": "material:ground", "property": "baseColor", "value": [0.6, 0.4, 0.3]},
 {"entity": "material:chrome", "property": "roughness", "value": 0.25},
 {"entity": "object:sphere", "property": "translation", "value": [0.4, 1.0, 0.0]}]
JSON
    ;;
    cornell_box) cat <<'JSON'
[{"entity": "light:ceiling_light", "property": "intensity", "value": 30},
 {"entity": "material:red", "property": "baseColor", "value": [0.2, 0.6, 0.2]},
 {"entity": "object:small_box", "property": "translation", "value": [0.2, 0.0, 0.1]}]
JSON
    ;;
    esac
}
scenes=(ring_on_ground glossy_sphere cornell_box)
for s in "${scenes[@]}"; do
    edits "$s" > "$out/$s.edits.json"
    echo "relight bench: $s latency (256^2 preview)"
    nice -n 10 "$cli" relight "resources/scenes/$s.wlscene" --edits "$out/$s.edits.json" --out "$out/$s-latency" \
        --report "$out/$s-latency.json" --preview 256 --width 256 --height 256 --threads 2 --coarse-level 3 >/dev/null
done
echo '[{"entity": "environment", "property": "intensity", "value": 1.0}]' > "$out/noop.edits.json"
for s in "${scenes[@]}"; do
    for p in 128 64 32; do
        echo "relight bench: $s preview $p vs ${spp} spp"
        nice -n 10 "$cli" relight "resources/scenes/$s.wlscene" --edits "$out/noop.edits.json" --out "$out/$s-p$p" \
            --report "$out/$s-p$p.json" --preview "$p" --width 128 --height 128 --reference-spp "$spp" --skip-full-rebuild \
            --coarse-level 3 >/dev/null
    done
    for k in 16 64 256 1024; do
        echo "relight bench: $s K=$k vs ${spp} spp"
        nice -n 10 "$cli" relight "resources/scenes/$s.wlscene" --edits "$out/noop.edits.json" --out "$out/$s-k$k" \
            --report "$out/$s-k$k.json" --preview 128 --width 128 --height 128 --keep "$k" --reference-spp "$spp" --skip-full-rebuild >/dev/null
    done
done
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
scenes = ["ring_on_ground", "glossy_sphere", "cornell_box"]
print("| scene | edit | kind | points touched | incremental ms (shared + per point) | image ms | from scratch ms | speed-up | coarse first answer ms (+ image) |")
print("|---|---|---|---|---|---|---|---|---|")
for s in scenes:
    r = json.load(open(f"{out}/{s}-latency.json"))
    for e in r["edits"]:
        print(f"| {s} | {e['entity']} {e['property']} | {e['kind']} | {e['pointsTouched']} | "
              f"{e['incrementalMs']:.1f} ({e['sharedFactorsMs']:.1f} + {e['perPointMs']:.1f}) | {e['imageMs']:.1f} | "
              f"{e['fullRebuildMs']:.0f} | {e['fullRebuildMs'] / max(e['incrementalMs'], 1e-3):.0f}x | "
              f"{e.get('coarseMs', float('nan')):.1f} (+ {e.get('coarseImageMs', float('nan')):.1f}) |")
print()
print("| scene | points (256^2) | build ms | bytes per point |")
print("|---|---|---|---|")
for s in scenes:
    p = json.load(open(f"{out}/{s}-latency.json"))["preview"]
    print(f"| {s} | {p['points']} | {p['buildMs']:.0f} | {p['bytesPerPoint']:.0f} |")
print()
print("| scene | relRMSE, preview 128^2 | 64^2 | 32^2 | build ms 128^2 / 64^2 / 32^2 | coarse (8^2 grid) first answer, 128^2 |")
print("|---|---|---|---|---|---|")
for s in scenes:
    rs = [json.load(open(f"{out}/{s}-p{p}.json")) for p in (128, 64, 32)]
    print(f"| {s} | " + " | ".join(f"{r['edits'][0]['relRMSE']:.3f}" for r in rs) + " | " +
          " / ".join(f"{r['preview']['buildMs']:.0f}" for r in rs) + f" | {rs[0]['edits'][0].get('coarseRelRMSE', float('nan')):.3f} |")
print()
print("| scene | K = 16 | 64 | 128 | 256 | 1024 (all) |")
print("|---|---|---|---|---|---|")
for s in scenes:
    vals = []
    for k in (16, 64, 128, 256, 1024):
        f = f"{out}/{s}-p128.json" if k == 128 else f"{out}/{s}-k{k}.json"
        vals.append(json.load(open(f))["edits"][0]["relRMSE"])
    print(f"| {s} | " + " | ".join(f"{v:.3f}" for v in vals) + " |")
PY
