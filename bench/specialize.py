#!/usr/bin/env python3
"""specialize.py -- generic against specialised kernels (issue 6), written to
bench/results/specialize.md: for each scene, the kernel build cold (empty
program cache and empty PoCL cache) and warm (both filled), the time to the
first sample (load + BVH + kernel build + the first 1-spp round), samples per
second over the whole render, device memory, and the relMSE of the
specialised image against the generic one rendered with the same seed (0
means the same bytes).

Usage: python3 bench/specialize.py [--size N] [--spp N]   (from any directory)
"""

import argparse
import csv
import json
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = [
    ("Cornell box", "scenes/cornell-box.gltf", []),
    ("glossy teapot", "scenes/cornell-teapot.gltf", []),
    ("glass sphere", "scenes/cornell-glass.gltf", []),
    ("DamagedHelmet", "../shared/scenes-real/DamagedHelmet/DamagedHelmet.glb", ["--env-uniform", "1"]),
]


def render(scene, extra, out, cache, pocl_cache, args):
    """One render in a process of its own (PoCL reads its cache folder once a
    process); its --stats-json statistics and --report checkpoints."""
    env = dict(os.environ, POCL_CACHE_DIR=pocl_cache)
    stats_path, report_path = out + ".json", out + ".csv"
    command = ["build/wavefront", "render", scene, "--width", str(args.size), "--spp", str(args.spp),
               "--seed", "7", "--cache-dir", cache, "-o", out, "--quiet", "--stats-json", stats_path,
               "--report", report_path] + extra
    subprocess.run(command, cwd=ROOT, env=env, check=True)
    with open(stats_path) as f:
        stats = json.load(f)
    with open(report_path) as f:
        checkpoints = list(csv.DictReader(f))
    times = stats["times"]
    return {
        "build": times["kernel_build"],
        "first": times["load"] + times["bvh_build"] + times["kernel_build"] + float(checkpoints[0]["seconds"]),
        "rate": stats["samples"] / times["render"] * 1e-6,
        "memory": stats["memory"]["device_bytes"] / 1048576.0,
        "features": stats["features"],
        "relmse": f"{float(checkpoints[-1]['relmse']):.4e}" if checkpoints[-1]["relmse"] else "",
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--spp", type=int, default=16)
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, scene, extra in SCENES:
            measured = {}
            for variant, flags in (("generic", ["--no-specialize"]), ("specialised", [])):
                cache, pocl = os.path.join(tmp, variant + name, "wf"), os.path.join(tmp, variant + name, "pocl")
                out = os.path.join(tmp, variant + ".exr")
                reference = [] if variant == "generic" else ["--reference", os.path.join(tmp, "generic.exr")]
                cold = render(scene, extra + flags + reference, out, cache, pocl, args)
                warm = render(scene, extra + flags + reference, out, cache, pocl, args)
                measured[variant] = (cold, warm)
            rows.append((name, measured))
    lines = [
        "# Generic against specialised kernels",
        "",
        f"`python3 bench/specialize.py --size {args.size} --spp {args.spp}`: {args.size} pixels wide, "
        f"{args.spp} spp, seed 7, on the development machine (PoCL 3.1, 2 cores of an AMD EPYC). "
        "Cold: empty program cache and empty PoCL cache; warm: the second run, both filled. "
        "First sample: load + BVH + kernel build + the first 1-spp round. Samples/s over the "
        "warm run. relMSE: the specialised image against the generic one.",
        "",
        "| scene | features compiled in | kernels | build cold (s) | build warm (s) | first sample cold (s) | first sample warm (s) | M samples/s | memory (MiB) | relMSE vs generic |",
        "|---|---|---|--:|--:|--:|--:|--:|--:|--:|",
    ]
    for name, measured in rows:
        for variant in ("generic", "specialised"):
            cold, warm = measured[variant]
            relmse = warm["relmse"] if variant == "specialised" else ""
            lines.append(f"| {name} | {warm['features']} | {variant} | {cold['build']:.2f} | {warm['build']:.3f} | "
                         f"{cold['first']:.2f} | {warm['first']:.2f} | {warm['rate']:.2f} | {warm['memory']:.1f} | {relmse} |")
    path = os.path.join(ROOT, "bench", "results", "specialize.md")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
