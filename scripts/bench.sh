#!/usr/bin/env bash
# Regenerates docs/performance-bench.md (and its plots in docs/img/): every sampler at equal time
# on the bundled scenes, on the Vulkan device and on the CPU tracer, against a long `mis` render
# of the CPU tracer. Timing varies with the machine and its load: run it on a quiet machine.
#   bash scripts/bench.sh [SECONDS_PER_SAMPLER]   (default 10; about 25x that per scene)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
size=${WAVELIT_BENCH_SIZE:-128}
bash scripts/build.sh release >/dev/null
cli=build/release/renderer/cli/wavelit-cli
out=out/perf
scenes=(resources/scenes/ring_on_ground.wlscene resources/scenes/glossy_sphere.wlscene
        resources/scenes/cornell_box.wlscene tests/bench/scenes/lambert_sun.wlscene
        tests/bench/scenes/glossy_sun.wlscene)
rm -rf "$out"
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .wlscene)
    mkdir -p "$out/$name"
    echo "bench: $name reference (mis, cpu, $((12 * seconds)) s)"
    "$cli" render "$scene" -o "$out/$name/reference.exr" --sampler mis --device cpu \
        --time $((12 * seconds)) --width "$size" --height "$size" --seed 4242 >/dev/null
    for device in vulkan cpu; do
        # The CPU oracle (a dense product per vertex) takes minutes per pass: Vulkan only.
        samplers=uniform,cosine,bsdf,env,mis,wavelet
        [ "$device" = vulkan ] && samplers=$samplers,oracle
        echo "bench: $name on $device"
        "$cli" bench "$scene" --reference "$out/$name/reference.exr" --time "$seconds" \
            --samplers "$samplers" --device "$device" --width "$size" --height "$size" \
            --out "$out/$name/$device" >/dev/null
    done
done
python3 scripts/perf_tables.py "$out" docs/performance-bench.md docs/img "$seconds"
echo "bench: wrote docs/performance-bench.md"
