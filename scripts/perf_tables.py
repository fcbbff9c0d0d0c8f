#!/usr/bin/env python3
"""Writes docs/performance-bench.md from the bench.json files scripts/bench.sh produced.

Usage: perf_tables.py OUT_DIR DOC.md IMG_DIR SECONDS
OUT_DIR/<scene>/<device>/bench.json -> one table per scene: per sampler and device the seconds per
pass, the spp reached, relRMSE, relRMSE^2 x spp (per-sample variance) and relRMSE^2 x seconds
(inverse efficiency), and that figure relative to the same device's `mis`.
"""
import datetime
import json
import os
import platform
import shutil
import subprocess
import sys


def git_head():
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def fmt(x, digits=3):
    return "—" if x is None else f"{x:.{digits}g}"


def main():
    out_dir, doc, img_dir, seconds = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
    os.makedirs(img_dir, exist_ok=True)
    lines = [
        "# Equal-time benchmark (generated)",
        "",
        "Written by `scripts/bench.sh` (do not edit by hand): every sampler renders each scene for "
        f"the same {seconds} s on each device; errors are against a `mis` render of the CPU tracer for "
        f"12x that time (its own error is included in every figure). Commit {git_head()}, "
        f"{datetime.date.today().isoformat()}, {os.cpu_count()} CPU threads, {platform.machine()}, "
        f"load average {os.getloadavg()[0]:.1f} when the tables were written (above the thread "
        "count, other work shared the machine: compare rows with each other, not with other runs).",
        "",
        "relRMSE = RMS over pixels and channels of (image − reference) / the reference's mean; "
        "relRMSE² × spp is the per-sample variance (lower is better per sample); relRMSE² × s is "
        "the inverse efficiency (lower is better at equal time); the last column divides it by the "
        "same device's `mis`.",
        "",
    ]
    for scene in sorted(os.listdir(out_dir)):
        rows = []
        for device in ("vulkan", "cpu"):
            path = os.path.join(out_dir, scene, device, "bench.json")
            if not os.path.exists(path):
                continue
            with open(path) as f:
                bench = json.load(f)
            runs = [r for r in bench["samplers"] if "skipped" not in r]
            mis = next((r.get("rel_mse_x_seconds") for r in runs if r["sampler"] == "mis"), None)
            for r in runs:
                eff = r.get("rel_mse_x_seconds")
                rows.append(f"| `{r['sampler']}` | {device} | {fmt(r.get('seconds_per_pass'))} | "
                            f"{r['spp']} | {fmt(r.get('rel_rmse'))} | {fmt(r.get('rel_mse_x_spp'))} | "
                            f"{fmt(eff)} | {fmt(eff / mis if eff and mis else None)} |")
            for r in bench["samplers"]:
                if "skipped" in r:
                    rows.append(f"| `{r['sampler']}` | {device} | skipped: {r['skipped']} ||||||")
            plot = os.path.join(out_dir, scene, device, "bench.png")
            if os.path.exists(plot):
                shutil.copy(plot, os.path.join(img_dir, f"bench_{scene}_{device}.png"))
            size = f"{bench['width']}×{bench['height']}"
        if not rows:
            continue
        lines += [f"## {scene} ({size})", "",
                  "| sampler | device | s/pass | spp | relRMSE | relRMSE²×spp | relRMSE²×s | ÷ mis |",
                  "|---|---|---|---|---|---|---|---|", *rows, ""]
        plots = [d for d in ("vulkan", "cpu")
                 if os.path.exists(os.path.join(img_dir, f"bench_{scene}_{d}.png"))]
        lines += [" ".join(f"![{scene} {d}](img/bench_{scene}_{d}.png)" for d in plots), ""]
    with open(doc + ".tmp", "w") as f:
        f.write("\n".join(lines))
    os.replace(doc + ".tmp", doc)


if __name__ == "__main__":
    main()
