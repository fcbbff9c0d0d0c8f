#!/usr/bin/env bash
# `wavelit-cli render` contract (architecture.md §6): exit 0 and files written for .exr/.png with a
# JSON report; exit 2 on bad usage; exit 1 naming the file for a missing or corrupt scene, mesh
# or environment map. Renders are tiny (32x32, 2 spp) because lavapipe shares the CPU.
# Usage: bash cli_render_test.sh <wavelit-cli> <source-dir>
set -u
source "$(dirname "$0")/cli_expect.sh"
export WAVELIT_VK_VALIDATION=1

# A private copy of the default scene's tree, so files can be broken one at a time.
copy_tree() {
    local dst="$1"
    mkdir -p "$dst"
    cp -r "$src/resources/scenes" "$src/resources/meshes" "$src/resources/lighting" "$dst/"
    mkdir -p "$dst/envmaps"
    cp "$src/resources/envmaps/studio.exr" "$dst/envmaps/"
}
copy_tree "$tmp/good"
scene="$tmp/good/scenes/ring_on_ground.wlscene"
small=(--width 32 --height 32 --spp 2 --device vulkan)

# Success: EXR, PNG and a report.
expect 0 -- render "$scene" -o "$tmp/out.exr" "${small[@]}" --report "$tmp/report.json"
[ -s "$tmp/out.exr" ] || fail "no EXR written"
grep -qF "$tmp/out.exr" "$tmp/out" || fail "stdout does not say where the EXR went: $(cat "$tmp/out")"
grep -q '"spp": 2' "$tmp/report.json" || fail "report lacks spp: $(cat "$tmp/report.json")"
grep -q '"validationMessages": 0' "$tmp/report.json" || fail "validation messages: $(cat "$tmp/report.json")"
grep -q '"pipelineSeconds"' "$tmp/report.json" || fail "report lacks timings"
expect 0 -- render "$scene" -o "$tmp/out.png" "${small[@]}" --seed 5 --bounces 2
[ -s "$tmp/out.png" ] || fail "no PNG written"
head -c 8 "$tmp/out.png" | od -An -tx1 | grep -q "89 50 4e 47" || fail "PNG signature missing"
expect 0 -- render "$scene" -o "$tmp/timed.exr" --width 16 --height 16 --time 0.2
# --also: the same image a second time (README command 1's EXR + PNG from one render).
expect 0 -- render "$scene" -o "$tmp/both.exr" --also "$tmp/both.png" --width 16 --height 16 --spp 1 --device cpu
[ -s "$tmp/both.exr" ] && [ -s "$tmp/both.png" ] || fail "--also did not write both files"
expect 2 ".jpg" -- render "$scene" -o "$tmp/x.exr" --also "$tmp/x.jpg"
[ -s "$tmp/timed.exr" ] || fail "--time render wrote nothing"

# Bad usage: exit 2.
expect 2 "--bogus" -- render "$scene" -o "$tmp/x.exr" --bogus 1
expect 2 -- render "$scene"
expect 2 ".jpg" -- render "$scene" -o "$tmp/x.jpg"
expect 2 "--spp" -- render "$scene" -o "$tmp/x.exr" --spp zero
expect 2 "--device" -- render "$scene" -o "$tmp/x.exr" --device gpu
expect 2 "--sampler" -- render "$scene" -o "$tmp/x.exr" --sampler nope

# Every sampler renders on Vulkan, and the oracle on the CPU too.
for sampler in uniform cosine bsdf env mis wavelet oracle; do
    expect 0 -- render "$scene" -o "$tmp/s_$sampler.exr" "${small[@]}" --sampler "$sampler"
    [ -s "$tmp/s_$sampler.exr" ] || fail "--sampler $sampler on vulkan wrote nothing"
done
expect 0 -- render "$scene" -o "$tmp/s_oracle.exr" --width 4 --height 4 --spp 1 --sampler oracle --device cpu

# The outlier tracer (issue 20): the N largest samples with their re-traced paths, on either device.
for device in cpu vulkan; do
    expect 0 -- render "$scene" -o "$tmp/o_$device.exr" --width 16 --height 16 --spp 4 --sampler mis \
        --device "$device" --trace-outliers 3 --outliers "$tmp/o_$device.json"
    [ "$(grep -c '"rank":' "$tmp/o_$device.json")" -eq 3 ] || fail "--trace-outliers 3 on $device: $(head -c 400 "$tmp/o_$device.json")"
    grep -q '"vertices": \[' "$tmp/o_$device.json" || fail "outliers on $device lack their paths"
done
expect 2 "--outliers" -- render "$scene" -o "$tmp/x.exr" --trace-outliers 3
expect 2 "--trace-outliers" -- render "$scene" -o "$tmp/x.exr" --trace-outliers 0 --outliers "$tmp/x.json"

# Bad input: exit 1 naming the file.
expect 1 "missing.wlscene" -- render "$tmp/missing.wlscene" -o "$tmp/x.exr" "${small[@]}"
echo '{ "format": "wavelit-scene", "version": 1, ' >"$tmp/corrupt.wlscene"
expect 1 "corrupt.wlscene" -- render "$tmp/corrupt.wlscene" -o "$tmp/x.exr" "${small[@]}"

copy_tree "$tmp/nomesh"
rm "$tmp/nomesh/meshes/torus.obj"
expect 1 "torus.obj" -- render "$tmp/nomesh/scenes/ring_on_ground.wlscene" -o "$tmp/x.exr" "${small[@]}"

copy_tree "$tmp/badexr"
head -c 300 "$src/resources/envmaps/studio.exr" >"$tmp/badexr/envmaps/studio.exr"
expect 1 "studio.exr" -- render "$tmp/badexr/scenes/ring_on_ground.wlscene" -o "$tmp/x.exr" "${small[@]}"
[ ! -e "$tmp/x.exr" ] || fail "a failed render wrote $tmp/x.exr"

if [ "$failures" -gt 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "cli render: all checks passed"
