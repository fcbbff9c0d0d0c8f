#!/usr/bin/env bash
# Makes the before/after pictures of docs/lightmix.md (docs/img/lightmix_*.png): the default scene
# under the night lighting setup rendered once with --light-groups, then remixed by
# `wavelit-cli mix` without rendering again. Also prints the mix times at the render's size.
#   bash scripts/lightmix_pictures.sh [WAVELIT_CLI] [SPP]   (defaults: build/rel's CLI, 64 spp)
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/rel/renderer/cli/wavelit-cli}
spp=${2:-64}
out=out/lightmix
img=docs/img
mkdir -p "$out" "$img"
sed 's/studio_soft.wllight/night_emissive.wllight/' resources/scenes/ring_on_ground.wlscene \
    >resources/scenes/.lightmix_night.wlscene
trap "rm -f resources/scenes/.lightmix_night.wlscene" EXIT
"$cli" render resources/scenes/.lightmix_night.wlscene -o "$out/night.exr" --light-groups \
    --width 240 --height 180 --spp "$spp" --sampler mis --device "${WAVELIT_DEVICE:-auto}"
ev=${WAVELIT_LIGHTMIX_EV:-0}
mix() { # mix NAME WEIGHTS
    "$cli" mix "$out/night.exr" -o "$img/lightmix_$1.png" --weights "$2" --exposure "$ev"
}
mix before window=1
mix warm_interior window=0.25,lamp=4,spot=0.5,environment=0.5
mix solo_lamp window=0,spot=0,environment=0
mix blue_spot spot=0.3:0.6:2.5,window=0.5

# Extract sun (docs/lightmix.md "Extract sun"): the glossy sphere under the city map alone,
# before and after `extract-sun`, and with the extracted sun moved (the map keeps its mask).
cat >resources/lighting/.lightmix_city.wllight <<'JSON'
{ "format": "wavelit-lighting", "version": 1, "name": "city only",
  "environment": { "map": "../envmaps/city.exr", "rotation": 30.0, "intensity": 1.0 },
  "lights": [] }
JSON
trap 'rm -f resources/scenes/.lightmix_night.wlscene resources/scenes/.lightmix_sun_*.wlscene \
    resources/lighting/.lightmix_city.wllight resources/lighting/.lightmix_extracted*.wllight' EXIT
"$cli" extract-sun resources/lighting/.lightmix_city.wllight -o resources/lighting/.lightmix_extracted.wllight
python3 - <<'PY'
import json
p = "resources/lighting/.lightmix_extracted.wllight"
setup = json.load(open(p))
sun = setup["lights"][-1]
sun["direction"] = [0.55, -0.45, 0.7]  # the extracted sun, moved to the other side
json.dump(setup, open(p.replace(".wllight", "_moved.wllight"), "w"), indent=2)
PY
for setup in city extracted extracted_moved; do
    sed "s#../lighting/sun_sky.wllight#../lighting/.lightmix_$setup.wllight#" resources/scenes/glossy_sphere.wlscene \
        >resources/scenes/.lightmix_sun_$setup.wlscene
    "$cli" render resources/scenes/.lightmix_sun_$setup.wlscene -o "$img/lightmix_sun_$setup.png" \
        --width 240 --height 180 --spp "$spp" --sampler mis --device "${WAVELIT_DEVICE:-auto}"
done

# A/B: the editor's split view between two snapshots of the night setup (warm | cool), remixes
# of one render, and warm against the cool setup with the lamp moved (a render side of its own)
# (needs the editor, build/rel/editor/wavelit or $WAVELIT).
wavelit=${WAVELIT:-$(dirname "$cli")/../../editor/wavelit}
if [ -x "$wavelit" ]; then
    WAVELIT_SCRIPT_OUT=$img QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen} "$wavelit" \
        resources/scenes/.lightmix_night.wlscene --light-mix --sampler mis --size 240x180 \
        --script scripts/lightmix_ab_picture.js
fi
