#!/usr/bin/env bash
# Remix latency of the editor at 256² and 512² (docs/lightmix.md "Remix latency"): the default
# scene under the night setup (4 groups), `wavelit --light-mix`, 9 intensity remixes each; prints
# each remix frame's status (its cost on the render thread) and the minimum and median per size.
#   bash scripts/lightmix_latency.sh [WAVELIT]   (default: build/rel/editor/wavelit)
set -euo pipefail
cd "$(dirname "$0")/.."
wavelit=${1:-build/rel/editor/wavelit}
sed 's/studio_soft.wllight/night_emissive.wllight/' resources/scenes/ring_on_ground.wlscene \
    >resources/scenes/.lightmix_latency.wlscene
trap 'rm -f resources/scenes/.lightmix_latency.wlscene' EXIT
for size in 256 512; do
    QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen} "$wavelit" resources/scenes/.lightmix_latency.wlscene \
        --light-mix --sampler mis --size ${size}x${size} --script scripts/lightmix_latency.js 2>&1 |
        grep "lightmix latency" | tee /dev/stderr | grep -o 'frame in [0-9.]*' | awk '{ print $3 }' | sort -n |
        awk -v s=$size '{ v[++n] = $1 } END { print s "x" s ": min " v[1] " ms, median " v[int((n + 1) / 2)] " ms, max " v[n] " ms (" n " remixes)" }'
done
