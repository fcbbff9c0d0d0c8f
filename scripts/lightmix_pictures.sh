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
trap 'rm -f resources/scenes/.lightmix_night.wlscene' EXIT
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
