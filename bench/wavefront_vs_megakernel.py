#!/usr/bin/env python3
"""wavefront_vs_megakernel.py -- issue 16's comparison: the wavefront's
schedules (refill, also with its extension queue sorted by material; group,
every stage inside each work-group, with its BSDF lanes and without) against
the megakernel on the three target scenes, interleaved round by round
so that the machine's load falls on all of them alike. Rates are samples over
the render's wall time, from `wavefront render --stats-json`; each setup's
kernels are compiled by a 1-spp render first (bench/throughput.py's render).
Prints a Markdown table: the rates of each round, and each schedule's median
ratio to the megakernel.

Usage: python3 bench/wavefront_vs_megakernel.py [--rounds N] [--width N] [--sampler S]
       (from any directory; about 8 minutes on 2 cores at the defaults)
"""

import argparse
import statistics
import tempfile

from throughput import REAL, render

SCENES = [  # name, path from the repository root, spp
    ("Cornell box", "scenes/cornell-box.gltf", 32),
    ("MetalRoughSpheresNoTextures (98 materials)",
     REAL + "MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf", 16),
    ("ToyCar (109 K triangles, textured)", REAL + "ToyCar/ToyCar.gltf", 16),
]
CONFIGS = [  # label, flags; the megakernel last
    ("refill", ["--schedule", "refill"]),
    ("refill, sorted", ["--schedule", "refill", "--sort-materials"]),
    ("group, no lanes", ["--schedule", "group", "--lane-width", "1"]),
    ("group", ["--schedule", "group"]),  # BSDF lanes as wide as the device's vectors
    ("megakernel", ["--integrator", "megakernel"]),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--width", type=int, default=512)
    parser.add_argument("--sampler", help="every configuration's --sampler (default: the renderer's, sobol)")
    args = parser.parse_args()
    sampler = ["--sampler", args.sampler] if args.sampler else []
    print(f"| scene | {' | '.join(label for label, _ in CONFIGS)} | "
          f"{' | '.join(label + ' / megakernel' for label, _ in CONFIGS[:-1])} |")
    print("|---|" + "--:|" * (2 * len(CONFIGS) - 1))
    with tempfile.TemporaryDirectory() as cache:
        for name, scene, spp in SCENES:
            rates = {label: [] for label, _ in CONFIGS}
            for _ in range(args.rounds):
                for label, flags in CONFIGS:
                    s = render(scene, ["--width", str(args.width), "--height", str(args.width), "--spp", str(spp)]
                               + sampler + flags, cache)
                    rates[label].append(s["samples"] / s["times"]["render"] * 1e-6)
            mega = statistics.median(rates["megakernel"])
            cells = [", ".join(f"{r:.2f}" for r in rates[label]) for label, _ in CONFIGS]
            ratios = [f"{statistics.median(rates[label]) / mega:.2f}" for label, _ in CONFIGS[:-1]]
            print(f"| {name}, {spp} spp | {' | '.join(cells)} | {' | '.join(ratios)} |", flush=True)


if __name__ == "__main__":
    main()
