#!/usr/bin/env bash
# `wavelit-cli render --light-groups` and `wavelit-cli mix` contract (issue 21, docs/lightmix.md):
# the EXR holds R,G,B and one <group>.R/.G/.B per light group (one per light by default, merged by
# a light's `group`, then `environment`); the memory is said before rendering; mix writes a file
# that mixes again, keeps unnamed groups at 1, and refuses unknown groups naming them (exit 1);
# bad usage exits 2. Numbers (layers sum to the beauty, mixes equal renders): the gtests
# light_groups_test, light_mix_test, gpu_light_groups_test. Renders are 8x8 `mis` on the CPU.
# Usage: bash cli_light_groups_test.sh <wavelit-cli> <source-dir>
set -u
source "$(dirname "$0")/cli_expect.sh"

mkdir -p "$tmp/envmaps"
cp -r "$src/resources/scenes" "$src/resources/meshes" "$src/resources/lighting" "$tmp/"
cp "$src/resources/envmaps/night.exr" "$src/resources/envmaps/studio.exr" "$tmp/envmaps/"
# The default scene under the night setup: window (rect), lamp (sphere), spot, environment.
sed 's/studio_soft.wllight/night_emissive.wllight/' "$tmp/scenes/ring_on_ground.wlscene" >"$tmp/scenes/night.wlscene"
scene="$tmp/scenes/night.wlscene"
base=(--width 8 --height 8 --spp 2 --seed 3 --bounces 2 --sampler mis --device cpu)
has_channel() { grep -qaF "$2" "$1" || fail "$1 has no channel $2"; }

expect 0 -- render "$scene" -o "$tmp/groups.exr" --light-groups "${base[@]}"
grep -qF "light groups: 4 layers of 12 bytes a pixel" "$tmp/out" || fail "memory not said up front: $(cat "$tmp/out")"
for c in R G B window.R window.G window.B lamp.R lamp.G lamp.B spot.R spot.B environment.R environment.G environment.B; do
    has_channel "$tmp/groups.exr" "$c"
done
grep -qaF "emission.R" "$tmp/groups.exr" && fail "an emission layer without emissive materials"

# The `group` property merges lamp and spot into one layer.
python3 - "$tmp/lighting/night_emissive.wllight" "$tmp/lighting/grouped.wllight" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
for l in d["lights"]:
    if l["name"] in ("lamp", "spot"):
        l["group"] = "practicals"
json.dump(d, open(sys.argv[2], "w"), indent=2)
PY
sed 's/studio_soft.wllight/grouped.wllight/' "$tmp/scenes/ring_on_ground.wlscene" >"$tmp/scenes/grouped.wlscene"
expect 0 -- render "$tmp/scenes/grouped.wlscene" -o "$tmp/grouped.exr" --light-groups "${base[@]}"
has_channel "$tmp/grouped.exr" practicals.R
grep -qaF "lamp.R" "$tmp/grouped.exr" && fail "a grouped light kept its own layer"

# mix: scalar and RGB weights; the output mixes again; an identity mix keeps every group.
expect 0 -- mix "$tmp/groups.exr" -o "$tmp/mixed.exr" --weights window=2,environment=0.5,lamp=1:0.5:0.25
grep -qF "4 light groups, 3 reweighted" "$tmp/out" || fail "mix did not report: $(cat "$tmp/out")"
has_channel "$tmp/mixed.exr" spot.R
expect 0 -- mix "$tmp/mixed.exr" -o "$tmp/mixed2.exr" --weights spot=0
expect 0 -- mix "$tmp/mixed.exr" -o "$tmp/mixed.png" --weights spot=0
[ -s "$tmp/mixed.png" ] || fail "mix wrote no PNG"

# Unknown groups: exit 1, naming every unknown one and the file's groups; nothing written.
expect 1 "groups.exr" "'sunn'" "'foo'" "its groups: environment, lamp, spot, window" -- \
    mix "$tmp/groups.exr" -o "$tmp/x.exr" --weights sunn=2,window=1,foo=0
# A render without layers: exit 1, saying how to get them.
expect 0 -- render "$scene" -o "$tmp/plain.exr" "${base[@]}"
expect 1 "plain.exr" "--light-groups" -- mix "$tmp/plain.exr" -o "$tmp/x.exr" --weights window=2
expect 1 "missing.exr" -- mix "$tmp/missing.exr" -o "$tmp/x.exr" --weights window=2
[ ! -e "$tmp/x.exr" ] || fail "a refused mix wrote $tmp/x.exr"

# Bad usage: exit 2.
expect 2 "--weights" -- mix "$tmp/groups.exr" -o "$tmp/x.exr"
expect 2 "'window'" -- mix "$tmp/groups.exr" -o "$tmp/x.exr" --weights window=-1
expect 2 "'window'" -- mix "$tmp/groups.exr" -o "$tmp/x.exr" --weights window=1:2
expect 2 "window=" -- mix "$tmp/groups.exr" -o "$tmp/x.exr" --weights window=
expect 2 "twice" -- mix "$tmp/groups.exr" -o "$tmp/x.exr" --weights window=1,window=2
expect 2 "IN.exr" -- mix -o "$tmp/x.exr" --weights window=1
expect 2 ".exr" -- mix "$tmp/groups.exr" -o "$tmp/x.txt" --weights window=1
expect 2 "--light-groups" -- render "$scene" -o "$tmp/x.png" --light-groups "${base[@]}"
expect 2 "--passes" -- render "$scene" -o "$tmp/x.exr" --light-groups --passes 0:2 "${base[@]}"

# The help text names both.
"$cli" --help >"$tmp/help" 2>&1
grep -qF -- "--light-groups" "$tmp/help" || fail "help does not mention --light-groups"
grep -qF "mix IN.exr" "$tmp/help" || fail "help does not mention mix"

if [ "$failures" -gt 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "cli light groups: all checks passed"
