#!/usr/bin/env bash
# README command 1: install what is missing, build, and run the main job.
#  - with a display (DISPLAY or WAYLAND_DISPLAY set): the editor on the bundled default scene;
#  - without one: a headless render of the default scene to out/ (EXR + PNG) plus its
#    speed/error report (out/ring_on_ground_report.json, summary printed).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh release
scene=resources/scenes/ring_on_ground.wlscene
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x build/release/editor/wavelit ]; then
    exec build/release/editor/wavelit "$scene" "$@"
fi
mkdir -p out
echo "run: no display; rendering $scene headless"
# The default sampler (wavelet) on the default device (Vulkan: lavapipe without a GPU), for a
# fixed time (WAVELIT_SPP=N renders N passes instead); one render writes the EXR and the PNG.
if [ -n "${WAVELIT_SPP:-}" ]; then budget=(--spp "$WAVELIT_SPP"); else
    budget=(--time "${WAVELIT_RENDER_SECONDS:-10}"); fi
build/release/renderer/cli/wavelit-cli render "$scene" -o out/ring_on_ground.exr \
    --also out/ring_on_ground.png "${budget[@]}" --report out/ring_on_ground_report.json "$@"
# Speed vs error at equal time on the default device, against the bundled converged reference
# (resources/references/README.md; without it, `bench` renders a short `mis` one first). The
# three samplers an artist chooses between by default; WAVELIT_BENCH_SAMPLERS picks others, e.g.
# all seven with the oracle, the ideal the wavelet sampler's efficiency is measured against
# (its kernel takes minutes to compile on lavapipe the first time).
reference=resources/references/ring_on_ground_128.exr
bench_reference=()
if [ -f "$reference" ]; then bench_reference=(--reference "$reference"); fi
build/release/renderer/cli/wavelit-cli bench "$scene" --time "${WAVELIT_BENCH_SECONDS:-2}" \
    --samplers "${WAVELIT_BENCH_SAMPLERS:-bsdf,mis,wavelet}" --width 128 --height 128 \
    "${bench_reference[@]}" --out out/bench
echo "run: images at $(pwd)/out/ring_on_ground.exr and $(pwd)/out/ring_on_ground.png"
echo "run: render report at $(pwd)/out/ring_on_ground_report.json"
echo "run: speed/error report at $(pwd)/out/bench/bench.{json,csv,png}"
