#!/usr/bin/env bash
# Issue 15: a hand-edited number no double holds (1e999) aborted `validate` with an uncaught JSON
# exception (exit 134), and an "extras" nested 100000 levels deep overflowed the stack (exit 139).
# Every command that loads such a file exits 1 with one message naming the file, the problem and its
# line; a refused render writes nothing.
# Usage: bash cli_number_overflow_test.sh <wavelit-cli> <source-dir>
set -u
source "$(dirname "$0")/cli_expect.sh"

setup="$src/tests/data/bad/number_overflow.wllight"
expect 1 "$setup: invalid JSON: number overflow parsing '1e999' at line 14" -- validate "$setup"

# A scene borrowing that setup, and scenes whose own numbers overflow (either sign, any spelling).
cp "$setup" "$src/resources/meshes/quad.obj" "$tmp/"
scene() { # LIGHTING-JSON CAMERA-POSITION-JSON
    cat <<JSON
{"format": "wavelit-scene", "version": 1, "name": "t",
 "camera": {"position": $2, "target": [0, 0, 0]},
 "materials": [{"id": 1, "name": "m", "brdf": "lambert"}],
 "objects": [{"id": 1, "name": "o", "mesh": "quad.obj", "material": 1}],
 "lighting": $1}
JSON
}
scene '"number_overflow.wllight"' '[0, 1, 4]' >"$tmp/borrows.wlscene"
scene '{"environment": {"intensity": 1}}' '[0, -1e999, 4]' >"$tmp/negative.wlscene"
scene '{"environment": {"intensity": 1}}' '[0, 1, 2.5E+308]' >"$tmp/upper.wlscene"
tiny=(--width 4 --height 4 --spp 1 --device cpu --sampler bsdf)
for cmd in validate render; do
    args=()
    [ "$cmd" = render ] && args=(-o "$tmp/x.exr" "${tiny[@]}")
    expect 1 "borrows.wlscene" "number_overflow.wllight: invalid JSON: number overflow parsing '1e999' at line 14" \
        -- "$cmd" "$tmp/borrows.wlscene" "${args[@]}"
    expect 1 "negative.wlscene: invalid JSON: number overflow parsing '-1e999' at line 2" \
        -- "$cmd" "$tmp/negative.wlscene" "${args[@]}"
    expect 1 "upper.wlscene: invalid JSON: number overflow parsing '2.5E+308' at line 2" \
        -- "$cmd" "$tmp/upper.wlscene" "${args[@]}"
done
[ ! -e "$tmp/x.exr" ] || fail "a refused render wrote $tmp/x.exr"

deep=$(printf '%*s' 100000 '' | tr ' ' '[')$(printf '%*s' 100000 '' | tr ' ' ']')
scene '{"environment": {"intensity": 1}, "extras": {"a": '"$deep"'}}' '[0, 1, 4]' >"$tmp/deep.wlscene"
for cmd in validate render; do
    args=()
    [ "$cmd" = render ] && args=(-o "$tmp/x.exr" "${tiny[@]}")
    expect 1 "deep.wlscene: invalid JSON: nested deeper than 256 levels at line 5" -- "$cmd" "$tmp/deep.wlscene" "${args[@]}"
done
[ ! -e "$tmp/x.exr" ] || fail "a refused render wrote $tmp/x.exr"

[ "$failures" -eq 0 ] && echo "cli_number_overflow: ok"
[ "$failures" -eq 0 ]
