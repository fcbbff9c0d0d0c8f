#!/usr/bin/env bash
# Inverse efficiency (relRMSE² × seconds, lower is better) of bsdf, mis and wavelet at 256² with
# five scattering vertices on three scenes equivalent to the production path tracer's figures of
# issue 12 (Blender Cycles 3.4, CPU, 2 threads, env NEE + BSDF MIS): a glossy sphere (ggx r = 0.2),
# a gold ring (ggx r = 0.1, our 4.6k-triangle torus) and a Lambert sphere, on a grey Lambert ground
# under the city HDRI with its small sun (tests/bench/scenes/*_sun.wlscene).
#   bash scripts/production_compare.sh [SPP] [REFERENCE_SPP]     (defaults 32 and 1024)
# How error and seconds are measured: scripts/equal_time.sh. Writes out/production/table.md.
set -euo pipefail
cd "$(dirname "$0")/.."
SIZE=256 SPP=${1:-32} REF_SPP=${2:-1024} OUT=out/production \
    COMPARE="glossy_r02_sun=0.12 ring_r01_sun=0.8 lambert_sun=0.002" \
    bash scripts/equal_time.sh tests/bench/scenes/glossy_r02_sun.wlscene \
    tests/bench/scenes/ring_r01_sun.wlscene tests/bench/scenes/lambert_sun.wlscene
