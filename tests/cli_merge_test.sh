#!/usr/bin/env bash
# `wavelit-cli render --passes` and `wavelit-cli merge` contract (issue 17, docs/farm.md): parts
# merge with exit 0; parts of different scenes or settings, overlapping pass ranges, and files
# that are not Wavelit renders (another EXR, a corrupt or truncated one) are refused with exit 1
# and a message naming the parts; bad usage exits 2. Every setting the header records is covered
# (width, sampler, seed, bounces, tracer; height is checked like width). Image equality:
# partial_merge_test.cpp. Renders are tiny (8x8, `mis`) so the whole script takes seconds.
# Usage: bash cli_merge_test.sh <wavelit-cli> <source-dir>
set -u
source "$(dirname "$0")/cli_expect.sh"

mkdir -p "$tmp/envmaps"
cp -r "$src/resources/scenes" "$src/resources/meshes" "$src/resources/lighting" "$tmp/"
cp "$src/resources/envmaps/studio.exr" "$tmp/envmaps/"
scene="$tmp/scenes/ring_on_ground.wlscene"
# A lighting variant: the same scene with the environment turned by 90 degrees.
sed 's/"rotation": 0.0/"rotation": 90.0/' "$tmp/lighting/studio_soft.wllight" >"$tmp/lighting/turned.wllight"
sed 's/studio_soft.wllight/turned.wllight/' "$scene" >"$tmp/scenes/turned.wlscene"
cmp -s "$scene" "$tmp/scenes/turned.wlscene" && fail "the variant scene did not change"
base=(--width 8 --height 8 --seed 3 --bounces 2 --sampler mis --device cpu)
part() { # part OUT FIRST:COUNT [extra flags...]
    local out="$1" passes="$2"
    shift 2
    expect 0 -- render "$scene" -o "$tmp/$out" --passes "$passes" "${base[@]}" "$@"
}

part a.exr 0:3
part b.exr 3:2
grep -qF "passes 3:2" "$tmp/out" || fail "render --passes does not say which passes: $(cat "$tmp/out")"
expect 0 -- merge "$tmp/a.exr" "$tmp/b.exr" -o "$tmp/ab.exr"
grep -qF "passes 0:5" "$tmp/out" || fail "merge does not say which passes: $(cat "$tmp/out")"
# A gap is allowed (every pass is an unbiased sample) and said.
part c.exr 7:1
expect 0 "gaps" -- merge "$tmp/a.exr" "$tmp/c.exr" -o "$tmp/ac.exr"

# Different scenes: the message names both parts and both scenes.
expect 0 -- render "$tmp/scenes/turned.wlscene" -o "$tmp/turned.exr" --passes 3:2 "${base[@]}"
expect 1 "a.exr" "turned.exr" "different scenes" "turned.wlscene" -- \
    merge "$tmp/a.exr" "$tmp/turned.exr" -o "$tmp/x.exr"
# Different settings, one at a time: the message names the parts and the setting.
part size.exr 3:2 --width 9
expect 1 "a.exr" "size.exr" "different width (8 vs 9)" -- merge "$tmp/a.exr" "$tmp/size.exr" -o "$tmp/x.exr"
part sampler.exr 3:2 --sampler env
expect 1 "a.exr" "sampler.exr" "different sampler (mis vs env)" -- merge "$tmp/a.exr" "$tmp/sampler.exr" -o "$tmp/x.exr"
part seed.exr 3:2 --seed 4
expect 1 "a.exr" "seed.exr" "different seed (3 vs 4)" -- merge "$tmp/a.exr" "$tmp/seed.exr" -o "$tmp/x.exr"
part bounces.exr 3:2 --bounces 3
expect 1 "a.exr" "bounces.exr" "different bounces (2 vs 3)" -- merge "$tmp/a.exr" "$tmp/bounces.exr" -o "$tmp/x.exr"
# The CPU and Vulkan tracers draw the same numbers but round differently: not one render.
WAVELIT_VK_VALIDATION=1 part tracer.exr 3:2 --device vulkan
grep -q "validation" "$tmp/err" && fail "Vulkan validation messages: $(cat "$tmp/err")"
expect 1 "a.exr" "tracer.exr" "different tracer (cpu vs vulkan)" -- merge "$tmp/a.exr" "$tmp/tracer.exr" -o "$tmp/x.exr"
# Overlapping pass ranges, also through a merged file.
part overlap.exr 2:2
expect 1 "a.exr (passes 0:3)" "overlap.exr (passes 2:2)" "overlap in passes 2..2" -- \
    merge "$tmp/overlap.exr" "$tmp/a.exr" -o "$tmp/x.exr"
expect 1 "ab.exr (passes 0:5)" "b.exr (passes 3:2)" "overlap" -- merge "$tmp/ab.exr" "$tmp/b.exr" -o "$tmp/x.exr"
expect 1 "a.exr" "overlap" -- merge "$tmp/a.exr" "$tmp/a.exr" -o "$tmp/x.exr"
[ ! -e "$tmp/x.exr" ] || fail "a refused merge wrote $tmp/x.exr"

# Not a Wavelit render: an environment map, a truncated part, a text file, a missing file.
expect 1 "studio.exr" "not a render written by wavelit-cli" -- merge "$tmp/a.exr" "$tmp/envmaps/studio.exr" -o "$tmp/x.exr"
head -c 400 "$tmp/b.exr" >"$tmp/truncated.exr"
expect 1 "truncated.exr" -- merge "$tmp/a.exr" "$tmp/truncated.exr" -o "$tmp/x.exr"
echo "not an image" >"$tmp/text.exr"
expect 1 "text.exr" -- merge "$tmp/text.exr" -o "$tmp/x.exr"
expect 1 "missing.exr" -- merge "$tmp/a.exr" "$tmp/missing.exr" -o "$tmp/x.exr"
[ ! -e "$tmp/x.exr" ] || fail "a refused merge wrote $tmp/x.exr"

# Bad usage: exit 2.
expect 2 "-o" -- merge "$tmp/a.exr" "$tmp/b.exr"
expect 2 ".exr" -- merge "$tmp/a.exr" "$tmp/b.exr" -o "$tmp/x.png"
expect 2 "PART.exr" -- merge -o "$tmp/x.exr"
expect 2 "--bogus" -- merge "$tmp/a.exr" --bogus -o "$tmp/x.exr"
expect 2 "--passes" "FIRST:COUNT" -- render "$scene" -o "$tmp/x.exr" --passes 3
expect 2 "--passes" -- render "$scene" -o "$tmp/x.exr" --passes -1:2
expect 2 "--passes" -- render "$scene" -o "$tmp/x.exr" --passes 0:0
expect 2 "--spp" -- render "$scene" -o "$tmp/x.exr" --passes 0:2 --spp 4
expect 2 "--time" -- render "$scene" -o "$tmp/x.exr" --passes 0:2 --time 1
expect 2 ".exr" -- render "$scene" -o "$tmp/x.png" --passes 0:2
expect 2 "--time" -- render "$scene" -o "$tmp/x.exr" --mpi --time 1
expect 2 "--report" -- render "$scene" -o "$tmp/x.exr" --mpi --spp 2 --report "$tmp/r.json"

if [ "$failures" -gt 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "cli merge: all checks passed"
