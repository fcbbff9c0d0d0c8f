#!/usr/bin/env bash
# Inverse efficiency (relRMSE² × seconds, lower is better) of bsdf, mis and wavelet at 256² with
# five scattering vertices on three scenes equivalent to the production path tracer's figures of
# issue 12 (Blender Cycles 3.4, CPU, 2 threads, env NEE + BSDF MIS): a glossy sphere (ggx r = 0.2),
# a gold ring (ggx r = 0.1, our 4.6k-triangle torus) and a Lambert sphere, on a grey Lambert ground
# under the city HDRI with its small sun (tests/bench/scenes/*_sun.wlscene).
#   bash scripts/production_compare.sh [SPP] [REFERENCE_SPP]     (defaults 32 and 256)
# Error: relRMSE of luminance (tests/bench/error_share_bench) against reference A, less the
# reference's own share, estimated from a second reference B of another seed (E|A−B|² = 2 var_ref).
# Seconds: the passes' worker CPU seconds from scripts/pass_cpu.py divided by the two threads,
# i.e. the wall time of a pass on an otherwise idle 2-core machine, whatever else runs now.
# Writes out/production/table.md.
set -euo pipefail
cd "$(dirname "$0")/.."
spp=${1:-32}
refSpp=${2:-256}
cli=build/release/renderer/cli/wavelit-cli
err=build/release/tests/bench/error_share_bench
out=out/production
mkdir -p "$out"
declare -A cycles=([glossy_r02_sun]=0.12 [ring_r01_sun]=0.8 [lambert_sun]=0.002)
declare -A refSampler=([glossy_r02_sun]=wavelet [ring_r01_sun]=wavelet [lambert_sun]=mis)
rel2() { "$err" "$1" "$2" 1 | sed -E 's/.*relRMSE2xspp ([0-9.e+-]+).*/\1/'; }
{
echo "| scene | sampler | relRMSE² × spp | s per pass (idle 2 cores) | relRMSE² × s | Cycles | ours / Cycles |"
echo "|---|---|---|---|---|---|---|"
} > "$out/table.md"
for name in glossy_r02_sun ring_r01_sun lambert_sun; do
    scene=tests/bench/scenes/$name.wlscene
    for seed in 9001 9002; do
        ref=$out/$name.ref$seed.exr
        [ -f "$ref" ] || "$cli" render "$scene" -o "$ref" --sampler "${refSampler[$name]}" \
            --spp "$refSpp" --seed "$seed" --device vulkan >/dev/null
    done
    refVar=$(python3 -c "print($(rel2 "$out/$name.ref9001.exr" "$out/$name.ref9002.exr") / 2)")
    for sampler in bsdf mis wavelet; do
        python3 scripts/pass_cpu.py - "$scene" "$sampler" 2 256 >/dev/null # warm the kernel
        cpu=$(python3 scripts/pass_cpu.py - "$scene" "$sampler" 5 256 | cut -d' ' -f1)
        sum=0
        for seed in 1 2 3; do
            "$cli" render "$scene" -o "$out/img.exr" --sampler "$sampler" --spp "$spp" \
                --seed "$seed" --device vulkan >/dev/null
            sum=$(python3 -c "print($sum + $(rel2 "$out/$name.ref9001.exr" "$out/img.exr"))")
        done
        python3 - "$name" "$sampler" "$sum" "$refVar" "$spp" "$cpu" "${cycles[$name]}" \
            >> "$out/table.md" <<'PY'
import sys
name, sampler, total, refVar, spp, cpu, cycles = sys.argv[1:]
perSample = max(float(total) / 3 - float(refVar), 0.0) * int(spp)
perPass = float(cpu) / 5 / 2
inv = perSample * perPass
print(f"| {name} | {sampler} | {perSample:.3g} | {perPass:.3f} | {inv:.3g} | {cycles} | {inv / float(cycles):.1f}× |")
PY
    done
done
cat "$out/table.md"
