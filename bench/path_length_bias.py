#!/usr/bin/env python3
"""path_length_bias.py -- the default bound on a path's bounces (issue 32):
what each bound costs in bias, and what an unbounded path costs in time.

Bias: every bench scene (throughput.py's, and ToyCar) is rendered with the
same seed at each bound and with `--max-depth unlimited`. Paths take the same
random numbers whatever the bound, so two renders differ only by what the
paths cut off would still have gathered: (mean unlimited - mean bounded) /
mean unlimited is that bound's bias, measured with the noise of the tail
alone. The group schedule renders these (it gives every schedule's bytes and
is the fastest on a CPU).

Time: a path trapped by total internal reflection (throughput 1, so roulette
never ends it) costs a global-queue schedule (refill: what `auto` picks on a
GPU) one launch a bounce. The glass-sphere Cornell box is rendered with
refill at each bound; the table gives its iterations and seconds.

Usage: python3 bench/path_length_bias.py [--size N] [--spp N] [--depths D,D,...]
       (about 5 minutes on 2 cores at the defaults, most of it the unbounded
       refill render)
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

from throughput import REAL, ROOT, SCENES

sys.path.insert(0, os.path.join(ROOT, "build", "python"))
import wavefront  # noqa: E402

BIAS_SCENES = SCENES + [("ToyCar", REAL + "ToyCar/ToyCar.gltf", ["--env-uniform", "1"])]
TRAPPED = "scenes/cornell-glass.gltf"


def render(scene, flags, out, cache):
    """Renders to `out` (EXR); returns the --stats-json statistics."""
    stats = out + ".json"
    subprocess.run(["build/wavefront", "render", scene, "-o", out, "--cache-dir", cache, "--quiet",
                    "--stats-json", stats] + flags, cwd=ROOT, check=True)
    with open(stats) as f:
        return json.load(f)


def longest_bucket(counts):
    """The report's last non-empty path-length bucket: 0, 1, 2-3, 4-7, ..., and the last open."""
    i = max(b for b, n in enumerate(counts) if n > 0)
    if i < 2:
        return str(i)
    lo = 1 << (i - 1)
    return f"{lo}+" if i == len(counts) - 1 else f"{lo}-{2 * lo - 1}"


def image_mean(path):
    return float(wavefront.read_image(path).mean())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--depths", default="16,32,64,128,256")
    args = parser.parse_args()
    depths = [int(d) for d in args.depths.split(",")]
    size = ["--width", str(args.size), "--height", str(args.size), "--spp", str(args.spp)]
    with tempfile.TemporaryDirectory() as tmp:
        cache = os.path.join(tmp, "cache")
        print(f"Bias: {args.size}x{args.size}, {args.spp} spp, seed 0, group schedule; "
              "(mean unlimited - mean bounded) / mean unlimited\n")
        print("| scene | image mean, unlimited | " + " | ".join(f"--max-depth {d}" for d in depths) + " |")
        print("|---|--:|" + "--:|" * len(depths))
        for name, scene, extra in BIAS_SCENES:
            flags = size + ["--schedule", "group"] + extra
            unlimited = os.path.join(tmp, "unlimited.exr")
            render(scene, flags + ["--max-depth", "unlimited"], unlimited, cache)
            reference = image_mean(unlimited)
            row = []
            for d in depths:
                bounded = os.path.join(tmp, f"depth-{d}.exr")
                render(scene, flags + ["--max-depth", str(d)], bounded, cache)
                row.append(f"{(reference - image_mean(bounded)) / reference:.1e}")
            print(f"| {name} | {reference:.5f} | " + " | ".join(row) + " |", flush=True)

        print(f"\nTime: {TRAPPED}, {args.size}x{args.size}, {args.spp} spp, seed 0, --schedule refill\n")
        print("| --max-depth | iterations | render seconds | longest paths (bounces) |")
        print("|---|--:|--:|---|")
        for d in ["unlimited"] + [str(d) for d in reversed(depths)]:
            stats = render(TRAPPED, size + ["--schedule", "refill", "--max-depth", d],
                           os.path.join(tmp, "trapped.exr"), cache)
            print(f"| {d} | {stats['iterations']} | {stats['times']['render']:.2f} | "
                  f"{longest_bucket(stats['path_lengths'])} |", flush=True)


if __name__ == "__main__":
    main()
