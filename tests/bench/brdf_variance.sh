#!/usr/bin/env bash
# Per-sample variance of `wavelet` against `mis` on one small scene per BRDF plugin (issue 16; the
# table in docs/brdfs.md): the bench scene glossy_sun (a sphere on a Lambert ground under the city
# map with its sun) with the sphere's material swapped for each plugin at r = 0.3, a converged
# `mis` reference per scene, then `wavelit-cli bench` at equal time, whose bench.json carries
# relRMSE^2 x spp (lower is better), read at the 32- and 64-spp checkpoints of both samplers
# (equal samples: the CPU `wavelet` builds product tables per hit and reaches ~1/150 of `mis`'s
# spp in equal time, so its end point is far earlier; the 4096-spp reference's own error adds
# only spp/4096 of mis's figure there). Images are 24 x 24 so `wavelet` gets past 64 spp.
# Not a test: timings and noise vary with the machine's load.
# Usage: bash tests/bench/brdf_variance.sh <wavelit-cli> <out-dir> [reference-spp] [seconds] [device] [seed]
set -eu
cli="$1"
out="$2"
ref_spp="${3:-4096}"
seconds="${4:-45}"
device="${5:-cpu}"
seed="${6:-7}"
src="$(cd "$(dirname "$0")/../.." && pwd)"
scenes="$src/tests/bench/scenes"
mkdir -p "$out"

# name brdf roughness anisotropy (measured: the shipped example, tabulated from glossy r = 0.5)
cases=("glossy glossy 0.3 0" "phong phong 0.3 0" "blinn blinn 0.3 0" "ward ward 0.3 0"
       "ward_aniso ward 0.3 0.8" "measured measured 0.5 0" "ggx ggx 0.3 0")
printf "| BRDF | setting | mis @32 | wavelet @32 | mis/wavelet @32 | mis @64 | wavelet @64 | mis/wavelet @64 | spp in equal time mis / wavelet |\n|---|---|---|---|---|---|---|---|---|\n" >"$out/table.md"
for c in "${cases[@]}"; do
    read -r name brdf rough aniso <<<"$c"
    scene="$scenes/brdf_variance_$name.wlscene"
    python3 - "$scenes/glossy_sun.wlscene" "$scene" "$brdf" "$rough" "$aniso" <<'PY'
import json, sys
src, dst, brdf, rough, aniso = sys.argv[1:6]
s = json.load(open(src))
m = s["materials"][0]
m["name"], m["brdf"], m["roughness"], m["anisotropy"] = brdf, brdf, float(rough), float(aniso)
m["baseColor"] = [0.9, 0.7, 0.5]
if brdf == "measured":
    m["brdfFile"] = "../../../resources/brdfs/glossy-copper-r05.binary"
    m["baseColor"] = [1.0, 1.0, 1.0]
s["render"]["width"] = s["render"]["height"] = 24
json.dump(s, open(dst, "w"), indent=2)
PY
    nice -n 10 "$cli" render "$scene" -o "$out/$name-ref.exr" --sampler mis --spp "$ref_spp" --device "$device" --seed 99 >/dev/null
    nice -n 10 "$cli" bench "$scene" --reference "$out/$name-ref.exr" --samplers mis,wavelet --time "$seconds" \
        --device "$device" --seed "$seed" --out "$out/$name" >/dev/null
    python3 - "$out/$name/bench.json" "$name" "$rough" "$aniso" >>"$out/table.md" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
runs = {r["sampler"]: r for r in j["samplers"]}
mean = j["reference_mean"]
def at(r, spp):
    p = [c for c in r["curve"] if c["spp"] == spp]
    return (p[0]["rmse"] / mean) ** 2 * spp if p else float("nan")
m, w = runs["mis"], runs["wavelet"]
cells = []
for spp in (32, 64):
    cells += [f"{at(m, spp):.4g}", f"{at(w, spp):.4g}", f"{at(m, spp) / at(w, spp):.2f}"]
print(f"| {sys.argv[2]} | r={sys.argv[3]} a={sys.argv[4]} | " + " | ".join(cells) + f" | {m['spp']} / {w['spp']} |")
PY
    rm -f "$scene"
done
cat "$out/table.md"
