#!/usr/bin/env bash
# Equal-time error of the Vulkan samplers, measured so that a loaded machine gives the same
# answer as a quiet one: inverse efficiency = relRMSE² × spp (per-sample error, independent of
# time) × seconds per pass on an idle 2-core machine (the passes' lavapipe worker CPU seconds from
# scripts/pass_cpu.py for SPP passes, median of 3 runs, per pass and halved; DEVICE=cpu: the C++
# tracer's). Lower is better; at equal time the RMSE² of two samplers is in the
# ratio of their inverse efficiencies.
#   bash scripts/equal_time.sh SCENE.wlscene... (env: SIZE 128, SPP 32, REF_SPP 2048,
#        SAMPLERS "bsdf mis wavelet", SEEDS "1 2 3", REF_SAMPLER mis, REF_DEVICE cpu,
#        OUT out/equal_time,
#        COMPARE "scene=value ..." adds a column: another renderer's relRMSE² × s per scene)
# Error: relRMSE of luminance (tests/bench/error_share_bench) against reference A at SEEDS
# (default "1 2 3"; fireflies move a 3-seed figure of the default scene by +-15%: give more seeds
# to compare two estimators, docs/performance.md "Wavelet pass cost, round 7"),
# less the reference's own share, estimated from a second reference B of another seed
# (E|A−B|² = 2 var_ref). References come from REF_SAMPLER on REF_DEVICE (the CPU tracer computes
# the same estimator, docs/estimator.md) and are kept in OUT between runs.
# Writes OUT/table.md; columns "× mis" and "× best" are the default sampler's inverse efficiency
# over `mis`'s and over the better of `bsdf` and `mis` (issue 12's equal-time conditions).
set -euo pipefail
cd "$(dirname "$0")/.."
size=${SIZE:-128}
spp=${SPP:-32}
refSpp=${REF_SPP:-2048}
samplers=(${SAMPLERS:-bsdf mis wavelet})
seeds=(${SEEDS:-1 2 3})
refSampler=${REF_SAMPLER:-mis}
refDevice=${REF_DEVICE:-cpu}
device=${DEVICE:-vulkan} # the device of the timed renders (pass_cpu.py reads DEVICE too)
out=${OUT:-out/equal_time}
cli=${CLI:-build/release/renderer/cli/wavelit-cli}
err=build/release/tests/bench/error_share_bench
declare -A compare=()
for kv in ${COMPARE:-}; do compare[${kv%%=*}]=${kv#*=}; done
mkdir -p "$out"
rel2() { "$err" "$1" "$2" 1 | sed -E 's/.*relRMSE2xspp ([0-9.e+-]+).*/\1/'; }
render() { "$cli" render "$1" -o "$2" --width "$size" --height "$size" "${@:3}" >/dev/null; }
table=$out/table.md
{
echo "| scene | sampler | relRMSE² × spp | s per pass (idle 2 cores) | relRMSE² × s | × mis | × best of bsdf/mis |${COMPARE:+ other | ours / other |}"
echo "|---|---|---|---|---|---|---|${COMPARE:+---|---|}"
} > "$table"
for scene in "$@"; do
    name=$(basename "$scene" .wlscene)
    for seed in 9001 9002; do
        ref=$out/$name.$size.ref$seed.exr
        [ -f "$ref" ] || render "$scene" "$ref" --sampler "$refSampler" --spp "$refSpp" \
            --seed "$seed" --device "$refDevice"
    done
    refVar=$(python3 -c "print($(rel2 "$out/$name.$size.ref9001.exr" "$out/$name.$size.ref9002.exr") / 2)")
    declare -A inv=()
    for sampler in "${samplers[@]}"; do
        python3 scripts/pass_cpu.py - "$scene" "$sampler" 2 "$size" >/dev/null # warm the kernel
        # The passes of the render whose error is measured (SPP of them, so a first pass that
        # builds a cache weighs as it does there), the median of three runs: one 5-pass run
        # swung +-20% at 128^2 under load.
        cpu=$(for run in 1 2 3; do
            python3 scripts/pass_cpu.py - "$scene" "$sampler" "$spp" "$size" | cut -d' ' -f1
        done | sort -g | sed -n 2p)
        sum=0
        for seed in "${seeds[@]}"; do
            render "$scene" "$out/img.exr" --sampler "$sampler" --spp "$spp" --seed "$seed" \
                --device "$device"
            sum=$(python3 -c "print($sum + $(rel2 "$out/$name.$size.ref9001.exr" "$out/img.exr"))")
        done
        read -r perSample perPass inv[$sampler] < <(python3 -c "
s = max($sum / ${#seeds[@]} - $refVar, 0.0) * $spp; p = $cpu / $spp / 2
print(f'{s:.4g} {p:.4f} {s * p:.4g}')")
        other=${compare[$name]:-}
        python3 - "$name" "$sampler" "$perSample" "$perPass" "${inv[$sampler]}" \
            "${inv[mis]:-}" "${inv[bsdf]:-}" "$other" >> "$table" <<'PY'
import sys
name, sampler, s, p, inv, mis, bsdf, other = sys.argv[1:]
inv = float(inv)
def ratio(x):
    return f"{inv / float(x):.2f}" if x and float(x) > 0 else "—"
best = min(float(v) for v in (mis, bsdf) if v) if (mis or bsdf) else 0.0
row = f"| {name} | {sampler} | {s} | {p} | {inv:.4g} | {ratio(mis)} | {ratio(best)} |"
if other:
    row += f" {other} | {inv / float(other):.1f}× |"
print(row)
PY
    done
    unset inv
done
cat "$table"
