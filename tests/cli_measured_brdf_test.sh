#!/usr/bin/env bash
# The `measured` BRDF from the command line (issue 16): a material's brdfFile is relative to the
# scene file, like a mesh; the shipped example renders; a file of the wrong size, with a NaN or a
# negative value, or a missing one, is a load error naming the file and the problem (exit 1), for
# `render` and `validate` alike. CPU renders of 4x4 pixels: no device needed.
# Usage: bash cli_measured_brdf_test.sh <wavelit-cli> <source-dir>
set -u
source "$(dirname "$0")/cli_expect.sh"
tiny=(--width 4 --height 4 --spp 1 --device cpu --sampler bsdf)

mkdir -p "$tmp/s/brdfs"
cp "$src/resources/meshes/quad.obj" "$tmp/s/"
example="$src/resources/brdfs/glossy-copper-r05.binary"
scene_with() { # BRDF-FILE: a one-object scene whose material is measured from that file
    cat <<JSON
{"format": "wavelit-scene", "version": 1, "name": "t",
 "camera": {"position": [0, 1, 4], "target": [0, 0, 0]},
 "materials": [{"id": 1, "name": "scan", "brdf": "measured", "brdfFile": "$1"}],
 "objects": [{"id": 1, "name": "o", "mesh": "quad.obj", "material": 1}],
 "lighting": {"environment": {"intensity": 1}}}
JSON
}

cp "$example" "$tmp/s/brdfs/good.binary"
scene_with brdfs/good.binary >"$tmp/s/good.wlscene"
expect 0 -- validate "$tmp/s/good.wlscene"
expect 0 -- render "$tmp/s/good.wlscene" -o "$tmp/good.exr" "${tiny[@]}"
[ -s "$tmp/good.exr" ] || fail "the measured example rendered nothing"

# put DOUBLE-BYTES OFFSET FILE: overwrite 8 bytes of the first value block.
put() { printf "$1" | dd of="$3" bs=1 seek="$2" conv=notrunc status=none; }

head -c 1000 "$example" >"$tmp/s/brdfs/short.binary"
cp "$example" "$tmp/s/brdfs/nan.binary"
put '\x00\x00\x00\x00\x00\x00\xf8\x7f' 20 "$tmp/s/brdfs/nan.binary"       # value 1: NaN
cp "$example" "$tmp/s/brdfs/negative.binary"
put '\x00\x00\x00\x00\x00\x00\xf0\xbf' 12 "$tmp/s/brdfs/negative.binary"  # value 0: -1
for case in "short:wrong size for a MERL BRDF file: expected 1,179,660 bytes for 24 x 64 x 32 bins, found 1,000" \
            "nan:non-finite value nan in the red channel at bin 1" \
            "negative:negative value -1.000000 in the red channel at bin 0" \
            "missing:cannot open the measured BRDF file"; do
    name="${case%%:*}"
    problem="${case#*:}"
    scene_with "brdfs/$name.binary" >"$tmp/s/$name.wlscene"
    for cmd in validate render; do
        args=()
        [ "$cmd" = render ] && args=(-o "$tmp/x.exr" "${tiny[@]}")
        expect 1 "$name.wlscene" "/materials/0/brdfFile" "$tmp/s/brdfs/$name.binary" "$problem" \
            -- "$cmd" "$tmp/s/$name.wlscene" "${args[@]}"
    done
done
[ ! -e "$tmp/x.exr" ] || fail "a refused render wrote $tmp/x.exr"

# A measured material must name its file.
sed 's/, "brdfFile": "brdfs\/good.binary"//' "$tmp/s/good.wlscene" >"$tmp/s/nofile.wlscene"
expect 1 "nofile.wlscene" "material 'scan' uses the measured BRDF but names no brdfFile" \
    -- render "$tmp/s/nofile.wlscene" -o "$tmp/x.exr" "${tiny[@]}"

[ "$failures" -eq 0 ] && echo "cli_measured_brdf: ok"
