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
import os
import re
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
    env = dict(os.environ, POCL_CACHE_DIR=pocl_cache)
    command = ["build/wavefront", "render", scene, "--width", str(args.size), "--spp", str(args.spp),
               "--seed", "7", "--cache-dir", cache, "-o", out] + extra
    text = subprocess.run(command, cwd=ROOT, env=env, check=True, capture_output=True, text=True).stdout
    times = re.search(r"load ([\d.]+) s, BVH build ([\d.]+) s .*kernel build ([\d.]+) s", text)
    first_round = re.search(r"^\s+([\d.]+)\s+1\s", text, re.M)
    rate = re.search(r"samples\s+\d+ at ([\d.]+) M/s", text)
    memory = re.search(r"memory\s+([\d.]+) MiB", text)
    features = re.search(r"^features\s+(.*)$", text, re.M)
    relmse = re.findall(r"^\s+[\d.]+\s+\d+\s+\S+\s+(\S+)\s", text, re.M)
    load, bvh, build = (float(x) for x in times.groups())
    return {
        "build": build,
        "first": load + bvh + build + float(first_round.group(1)),
        "rate": float(rate.group(1)),
        "memory": float(memory.group(1)),
        "features": features.group(1),
        "relmse": relmse[-1] if relmse else "",
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
