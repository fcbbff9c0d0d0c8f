#!/usr/bin/env bash
# What `validate` refuses, `render` refuses too, with the same message: unknown BRDFs and unknown
# keys (with a "did you mean") are load errors naming the file, the material or key, and the JSON
# path; "extras" is kept and never a problem; repairs (zero-area triangles) stay warnings that
# `render` prints while it renders. CPU renders of 4x4 pixels, so no device is needed.
# Usage: bash cli_load_problems_test.sh <wavelit-cli> <source-dir>
set -u
source "$(dirname "$0")/cli_expect.sh"
bad="$src/tests/data/bad"
good="$src/tests/data/good"
tiny=(--width 4 --height 4 --spp 1 --device cpu --sampler bsdf)

brdf_problem="material 'ground' (/materials/1/brdf): unknown BRDF 'no_such_brdf'; known: lambert, ggx, glossy, phong, blinn, ward, measured"
key_problem="unknown key 'roughnes' in /materials/0 (did you mean 'roughness'?)"
for cmd in validate render; do
    args=()
    [ "$cmd" = render ] && args=(-o "$tmp/x.exr" "${tiny[@]}")
    expect 1 "unknown_brdf.wlscene" "$brdf_problem" -- "$cmd" "$bad/unknown_brdf.wlscene" "${args[@]}"
    expect 1 "typo_key.wlscene" "$key_problem" -- "$cmd" "$bad/typo_key.wlscene" "${args[@]}"
done
expect 1 "unknown_key.wllight" "unknown key 'intensty' in /lights/0 (did you mean 'intensity'?)" \
    -- validate "$bad/unknown_key.wllight"
[ ! -e "$tmp/x.exr" ] || fail "a refused render wrote $tmp/x.exr"

# Several problems: one error, one line each.
mkdir -p "$tmp/bad"
cp "$src/resources/meshes/quad.obj" "$bad/some_zero_area.obj" "$tmp/bad/"
scene_with() { # MATERIAL-JSON MESH: a one-object scene
    cat <<JSON
{"format": "wavelit-scene", "version": 1, "name": "t",
 "camera": {"position": [0, 1, 4], "target": [0, 0, 0]},
 "materials": [$1],
 "objects": [{"id": 1, "name": "o", "mesh": "$2", "material": 1}],
 "lighting": {"environment": {"intensity": 1}}}
JSON
}
scene_with '{"id": 1, "name": "m", "brdf": "toon", "roughnes": 0.3, "basecolor": [1, 1, 1]}' quad.obj >"$tmp/bad/two.wlscene"
for cmd in validate render; do
    args=()
    [ "$cmd" = render ] && args=(-o "$tmp/x.exr" "${tiny[@]}")
    expect 1 "two.wlscene: 3 problems:" "  unknown key 'roughnes' in /materials/0 (did you mean 'roughness'?)" \
        "  unknown key 'basecolor' in /materials/0 (did you mean 'baseColor'?)" \
        "  material 'm' (/materials/0/brdf): unknown BRDF 'toon'; known: lambert, ggx, glossy, phong, blinn, ward, measured" \
        -- "$cmd" "$tmp/bad/two.wlscene" "${args[@]}"
done

# "extras" everywhere: valid, renders, no warning.
expect 0 -- validate "$good/extras.wlscene"
grep -qF "extras.wlscene: ok: " "$tmp/out" || fail "validate extras.wlscene: $(cat "$tmp/out")"
expect 0 -- render "$good/extras.wlscene" -o "$tmp/extras.exr" "${tiny[@]}"
[ -s "$tmp/extras.exr" ] || fail "extras.wlscene rendered nothing"
grep -q "warning" "$tmp/err" && fail "extras.wlscene gave warnings: $(cat "$tmp/err")"

# A repair stays a warning: render prints it and renders; validate refuses.
scene_with '{"id": 1, "name": "m", "brdf": "lambert"}' some_zero_area.obj >"$tmp/bad/repaired.wlscene"
expect 0 "warning: " "skipped 1 zero-area triangles of 2" -- render "$tmp/bad/repaired.wlscene" -o "$tmp/r.exr" "${tiny[@]}"
[ -s "$tmp/r.exr" ] || fail "repaired.wlscene rendered nothing"
expect 1 "skipped 1 zero-area triangles of 2" -- validate "$tmp/bad/repaired.wlscene"

[ "$failures" -eq 0 ] && echo "cli_load_problems: ok"
[ "$failures" -eq 0 ]
