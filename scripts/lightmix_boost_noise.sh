#!/usr/bin/env bash
# Noise of a light boosted x4 by a LightMix remix against a fresh render of the boosted scene at
# equal time (docs/lightmix.md "Cost of the layers, and a boosted light's noise"): the default
# scene under the night setup (4 groups), the lamp x4, 128x96, `mis`. A reference of the boosted
# scene at REF_SPP; then, interleaved, REPS times: (a) the night setup rendered with
# --light-groups for SECONDS and remixed with lamp=4 (`wavelit-cli mix`), (b) the boosted setup
# rendered plainly for SECONDS; each against the reference (luminance RMSE, the editor's
# app.compareImages). Prints the passes each reached and the errors, and the medians.
#   bash scripts/lightmix_boost_noise.sh [WAVELIT_CLI] [SECONDS] [REPS] [REF_SPP]
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/release/renderer/cli/wavelit-cli}
seconds=${2:-3}
reps=${3:-3}
refspp=${4:-1024}
wavelit=${WAVELIT:-$(dirname "$cli")/../../editor/wavelit}
out=$(mktemp -d /tmp/lightmix_noise.XXXXXX)
size="--width 128 --height 96 --sampler mis --device ${WAVELIT_DEVICE:-auto}"
sed 's/studio_soft.wllight/night_emissive.wllight/' resources/scenes/ring_on_ground.wlscene \
    >resources/scenes/.lightmix_noise_night.wlscene
python3 - <<'PY'
import json
setup = json.load(open("resources/lighting/night_emissive.wllight"))
for light in setup["lights"]:
    if light["name"] == "lamp":
        light["intensity"] *= 4
json.dump(setup, open("resources/lighting/.lightmix_noise_boost.wllight", "w"), indent=2)
PY
sed 's#studio_soft.wllight#.lightmix_noise_boost.wllight#' resources/scenes/ring_on_ground.wlscene \
    >resources/scenes/.lightmix_noise_boost.wlscene
trap 'rm -f resources/scenes/.lightmix_noise_*.wlscene resources/lighting/.lightmix_noise_boost.wllight' EXIT
spp() { grep -o '[0-9]* spp' "$1" | tail -1; }
"$cli" render resources/scenes/.lightmix_noise_boost.wlscene -o "$out/ref.exr" $size --spp "$refspp" --seed 99 \
    >"$out/ref.log" 2>&1
echo "reference: $(spp "$out/ref.log")"
for i in $(seq 1 "$reps"); do
    "$cli" render resources/scenes/.lightmix_noise_night.wlscene -o "$out/layers_$i.exr" $size --light-groups \
        --time "$seconds" --seed "$i" >"$out/mix_$i.log" 2>&1
    "$cli" mix "$out/layers_$i.exr" -o "$out/mix_$i.exr" --weights lamp=4 >/dev/null
    "$cli" render resources/scenes/.lightmix_noise_boost.wlscene -o "$out/fresh_$i.exr" $size \
        --time "$seconds" --seed "$i" >"$out/fresh_$i.log" 2>&1
    echo "rep $i: remix $(spp "$out/mix_$i.log"), fresh $(spp "$out/fresh_$i.log")"
done
LIGHTMIX_NOISE_DIR=$out LIGHTMIX_NOISE_REPS=$reps QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen} \
    "$wavelit" --script scripts/lightmix_boost_noise.js 2>&1 | grep "lightmix noise"
