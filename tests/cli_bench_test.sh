#!/usr/bin/env bash
# `wavelit-cli bench` contract (architecture.md §6): writes bench.json/csv/png and one EXR per sampler
# that ran; RMSE against the reference falls as samples accumulate (Monte Carlo: ~1/sqrt(spp));
# exit 2 on bad usage, 1 naming a missing scene or a reference of the wrong size. Tiny renders.
# Usage: bash cli_bench_test.sh <wavelit-cli> <source-dir>
set -u
source "$(dirname "$0")/cli_expect.sh"
export WAVELIT_VK_VALIDATION=1
# The ring under the soft studio setup: light-tailed enough that RMSE falls within a second.
scene="$src/resources/scenes/ring_on_ground.wlscene"

expect 0 -- bench "$scene" --samplers bsdf --time 1 --width 24 --height 24 --out "$tmp/b"
for f in bench.json bench.csv bench.png bsdf.exr reference.exr; do
    [ -s "$tmp/b/$f" ] || fail "bench did not write $f"
done
# The first checkpoint (1 spp) must have a larger RMSE than the last one.
if [ -s "$tmp/b/bench.csv" ]; then
    first=$(awk -F, 'NR == 2 {print $4}' "$tmp/b/bench.csv")
    last=$(tail -n 1 "$tmp/b/bench.csv" | awk -F, '{print $4}')
    awk -v a="$first" -v b="$last" 'BEGIN { exit !(a > b && b > 0) }' ||
        fail "RMSE did not fall: first $first, last $last"
    "$cli" validate "$tmp/b/bsdf.exr" >/dev/null 2>&1 || fail "bsdf.exr does not validate"
fi

# Bad usage (no --out, an unknown sampler): exit 2; a missing scene and a reference of the wrong
# size: exit 1 naming them.
expect 2 -- bench "$scene" --time 0.1
expect 2 -- bench "$scene" --samplers bogus --out "$tmp/c"
expect 1 none.wlscene -- bench "$tmp/none.wlscene" --out "$tmp/d"
expect 1 "24x24" -- bench "$scene" --reference "$tmp/b/bsdf.exr" --width 16 --height 16 --samplers bsdf \
    --time 0.1 --out "$tmp/e"

if [ "$failures" -eq 0 ]; then echo "cli_bench_test: all checks passed"; exit 0; fi
echo "cli_bench_test: $failures failure(s)"; exit 1
