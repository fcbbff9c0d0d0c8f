#!/usr/bin/env bash
# `wavelit-cli relight` contract (docs/relighting.md, architecture.md §6): one EXR per edit and a
# report with the documented keys per edit; relRMSE null without --reference-spp and a number with
# it; exit 1 naming the file for a bad edits file (bad JSON, unknown entity or property, a value
# out of range or of the wrong type) or a missing scene; exit 2 on bad usage. Tiny sizes (16x16
# output, 8x8 preview points, an 8x8 sphere grid) keep it fast.
# Usage: bash cli_relight_test.sh <wavelit-cli> <source-dir>
set -u
source "$(dirname "$0")/cli_expect.sh"

scene="$src/resources/scenes/ring_on_ground.wlscene"
small=(--width 16 --height 16 --preview 8 --level 3 --keep 16)
cat > "$tmp/edits.json" <<'JSON'
[
  {"entity": "environment", "property": "rotation", "value": 90},
  {"entity": "softbox", "property": "intensity", "value": 90},
  {"entity": "material:ground", "property": "baseColor", "value": [0.3, 0.5, 0.7]},
  {"entity": "object:ring", "property": "translation", "value": [0.3, 0.12, 0.0]},
  {"entity": "object:ring", "property": "material", "value": "ground"}
]
JSON
expect 0 -- relight "$scene" --edits "$tmp/edits.json" --out "$tmp/previews" --report "$tmp/r.json" "${small[@]}"
for i in 0 1 2 3 4; do
    [ -s "$tmp/previews/edit_$i.exr" ] || fail "edit_$i.exr not written"
done
[ -e "$tmp/previews/edit_5.exr" ] && fail "an EXR for an edit that does not exist"
for key in '"edits"' '"entity"' '"property"' '"kind"' '"factorsRebuilt"' '"pointsTouched"' \
           '"incrementalMs"' '"incrementalCpuMs"' '"fullRebuildMs"' '"relRMSE": null'; do
    grep -qF "$key" "$tmp/r.json" || fail "report lacks $key: $(cat "$tmp/r.json")"
done
for kind in environment light material object; do
    grep -qF "\"kind\": \"$kind\"" "$tmp/r.json" || fail "report lacks kind $kind"
done
# The incremental previews equal from-scratch builds (architecture.md §8).
grep -E '"maxRelDiffVsFullRebuild": [0-9.e+-]+' "$tmp/r.json" | grep -vqE ': (0|0\.0|[0-9.]+e-(0[7-9]|[1-9][0-9]))(,)?$' &&
    fail "an incremental preview differs from its full rebuild: $(grep maxRelDiff "$tmp/r.json")"

# With a reference: relRMSE is a number.
echo '[{"entity": "environment", "property": "intensity", "value": 1.5}]' > "$tmp/one.json"
expect 0 -- relight "$scene" --edits "$tmp/one.json" --out "$tmp/ref" --report "$tmp/ref.json" "${small[@]}" --reference-spp 2
grep -qE '"relRMSE": [0-9]' "$tmp/ref.json" || fail "relRMSE not a number: $(cat "$tmp/ref.json")"

# Coarse-to-fine: --coarse-level writes the first answer per edit and reports its cost and error.
expect 0 -- relight "$scene" --edits "$tmp/one.json" --out "$tmp/coarse" --report "$tmp/coarse.json" "${small[@]}" \
    --coarse-level 2 --reference-spp 2
[ -s "$tmp/coarse/edit_0_coarse.exr" ] || fail "edit_0_coarse.exr not written"
for key in '"coarse": {' '"coarseMs"' '"coarseImageMs"' '"coarseRelRMSE"'; do
    grep -qF "$key" "$tmp/coarse.json" || fail "coarse report lacks $key: $(cat "$tmp/coarse.json")"
done
expect 2 "--coarse-level" -- relight "$scene" --edits "$tmp/one.json" --out "$tmp/x" --report "$tmp/x.json" --coarse-level 9

# The shadow-field drag (docs/relighting.md §7.0e, §7.0j, §7.0k): with --field-carry-own the ring's
# own points carry their visibility (statesCarried), with --field-lobe-cut their narrow lobes are
# cut, and the report says so; small field.
cat > "$tmp/drag.json" <<'JSON'
[{"entity": "object:ring", "property": "translation", "value": [0.05, 0.12, 0.0]},
 {"entity": "object:ring", "property": "translation", "value": [0.08, 0.12, 0.02]}]
JSON
expect 0 -- relight "$scene" --edits "$tmp/drag.json" --out "$tmp/field" --report "$tmp/field.json" \
    --width 32 --height 32 --preview 32 --level 3 --keep 16 --shadow-field --field-shells 4 --field-directions 3 \
    --field-check --field-carry-own --field-lobe-cut 2
for key in '"carryOwnStates": true' '"carriedLobeCut": 2' '"method": "shadowField"' '"fieldVsExactRelRMSE"'; do
    grep -qF "$key" "$tmp/field.json" || fail "field report lacks $key: $(cat "$tmp/field.json")"
done
grep -qE '"statesCarried": [1-9]' "$tmp/field.json" || fail "no own point carried: $(grep statesCarried "$tmp/field.json")"

# Bad input: exit 1, the message names the file and the problem.
echo '[{"entity": "lamp", "property": "intensity", "value": 1}]' > "$tmp/entity.json"
expect 1 "entity.json" "no entity named 'lamp'" -- relight "$scene" --edits "$tmp/entity.json" --out "$tmp/x" --report "$tmp/x.json" "${small[@]}"
echo '[{"entity": "environment", "property": "spin", "value": 1}]' > "$tmp/property.json"
expect 1 "property.json" "unknown property 'spin'" -- relight "$scene" --edits "$tmp/property.json" --out "$tmp/x" --report "$tmp/x.json" "${small[@]}"
echo '[{"entity": "material:gold", "property": "roughness", "value": 7}]' > "$tmp/range.json"
expect 1 "range.json" "roughness" -- relight "$scene" --edits "$tmp/range.json" --out "$tmp/x" --report "$tmp/x.json" "${small[@]}"
echo '[{"entity": "environment", "property": "rotation", "value": "east"}]' > "$tmp/type.json"
expect 1 "type.json" "rotation" -- relight "$scene" --edits "$tmp/type.json" --out "$tmp/x" --report "$tmp/x.json" "${small[@]}"
echo '[{"entity": "environment", "property": ' > "$tmp/broken.json"
expect 1 "broken.json" "not valid JSON" -- relight "$scene" --edits "$tmp/broken.json" --out "$tmp/x" --report "$tmp/x.json" "${small[@]}"
echo '{"entity": "environment"}' > "$tmp/object.json"
expect 1 "object.json" "array" -- relight "$scene" --edits "$tmp/object.json" --out "$tmp/x" --report "$tmp/x.json" "${small[@]}"
expect 1 "missing.json" -- relight "$scene" --edits "$tmp/missing.json" --out "$tmp/x" --report "$tmp/x.json" "${small[@]}"
expect 1 "nope.wlscene" -- relight "$tmp/nope.wlscene" --edits "$tmp/edits.json" --out "$tmp/x" --report "$tmp/x.json"
[ -e "$tmp/x.json" ] && fail "a report was written for bad input"

# Bad usage: exit 2.
expect 2 "--edits" -- relight "$scene" --out "$tmp/x" --report "$tmp/x.json"
expect 2 "--bogus" -- relight "$scene" --edits "$tmp/edits.json" --out "$tmp/x" --report "$tmp/x.json" --bogus 1
expect 2 "--keep" -- relight "$scene" --edits "$tmp/edits.json" --out "$tmp/x" --report "$tmp/x.json" --keep 0

[ "$failures" -eq 0 ] && echo "cli_relight_test: ok"
exit $(( failures > 0 ))
