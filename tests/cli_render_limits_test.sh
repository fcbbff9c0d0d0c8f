#!/usr/bin/env bash
# Limits said up front (issue 15, renderer/render/gpu/render_limits.h): a render the Vulkan device cannot
# hold is refused before anything is allocated or rendered, exit 1, with a message naming the size,
# the device's limit, by how much it is exceeded and what to do. `timeout` turns a render that was
# started anyway (16384^2 on lavapipe would take hours) into a failure.
# Usage: bash cli_render_limits_test.sh <wavelit-cli> <source-dir>
set -u
CLI_TIMEOUT=120
source "$(dirname "$0")/cli_expect.sh"
export WAVELIT_VK_VALIDATION=1
scene="$src/resources/scenes/ring_on_ground.wlscene"

# The accumulation buffer (16 bytes a pixel) of 16384x16384 is 4 GiB; lavapipe's storage buffers
# hold 128 MiB (maxStorageBufferRange). Both the default sampler (tables) and bsdf are refused
# before the pipeline is compiled.
for sampler in wavelet bsdf; do
    expect 1 "the render size 16384x16384 is too big for" "accumulation buffer needs 4096.0 MiB" \
        "more than the device's storage-buffer limit of" "(maxStorageBufferRange)" \
        "render at a smaller size: at most" \
        -- render "$scene" -o "$tmp/x.exr" --width 16384 --height 16384 --device vulkan \
        --sampler "$sampler" --spp 1
done
# --device auto reports the same instead of moving the render to the CPU tracer.
expect 1 "the render size 16384x16384 is too big for" "(maxStorageBufferRange)" \
    -- render "$scene" -o "$tmp/x.exr" --width 16384 --height 16384 --device auto --spp 1
[ ! -e "$tmp/x.exr" ] || fail "a refused render wrote $tmp/x.exr"

if [ "$failures" -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "all render-limit checks passed"
