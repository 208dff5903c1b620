#!/usr/bin/env python3
"""roulette_study.py -- Russian roulette chosen by efficiency (issue 27): the
start depth (--roulette-depth) and the survival rule (q = min(cap, max
throughput), --roulette-cap) measured by 1 / (relMSE x seconds) at equal
work, on the Cornell box, its glass-sphere variant (light trapped by total
internal reflection) and MetalRoughSpheresNoTextures. Each scene's reference
is rendered once with today's rule at REF_SPP; every configuration then
renders STUDY_SPP, interleaved round by round (a new seed a round), and its
relMSE against the reference and its render time come from the renderer's
--report CSV and --stats-json. Prints a Markdown table: each configuration's
median relMSE, seconds and efficiency, relative to today's.

Usage: python3 bench/roulette_study.py [--size N] [--spp N] [--ref-spp N] [--rounds N]
       (about 6 minutes on 2 cores at the defaults; run it on an idle machine)
"""

import argparse
import csv
import json
import os
import statistics
import subprocess
import tempfile

from throughput import REAL, ROOT

SCENES = [  # name, path from the repository root
    ("Cornell box", "scenes/cornell-box.gltf"),
    ("Cornell box, glass sphere", "scenes/cornell-glass.gltf"),
    ("MetalRoughSpheresNoTextures", REAL + "MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf"),
]
CONFIGS = [  # label, flags; today's rule first
    ("depth 5, q = max throughput (today)", ["--roulette-depth", "5", "--roulette-cap", "1"]),
    ("depth 5, q <= 0.95 (Mitsuba 3)", ["--roulette-depth", "5", "--roulette-cap", "0.95"]),
    ("depth 3, q = max throughput", ["--roulette-depth", "3", "--roulette-cap", "1"]),
    ("depth 3, q <= 0.95", ["--roulette-depth", "3", "--roulette-cap", "0.95"]),
    ("depth 1, q <= 0.95", ["--roulette-depth", "1", "--roulette-cap", "0.95"]),
]


def render(scene, flags, out, cache, extra=()):
    """Renders; returns (relMSE at the last checkpoint or None, render seconds)."""
    with tempfile.TemporaryDirectory() as tmp:
        stats, report = os.path.join(tmp, "stats.json"), os.path.join(tmp, "report.csv")
        subprocess.run(["build/wavefront", "render", scene, "-o", out, "--cache-dir", cache, "--quiet",
                        "--stats-json", stats, "--report", report] + flags + list(extra),
                       cwd=ROOT, check=True)
        with open(stats) as f:
            seconds = json.load(f)["times"]["render"]
        with open(report) as f:
            rows = list(csv.DictReader(f))
        relmse = rows[-1]["relmse"]
        return (float(relmse) if relmse else None), seconds


def study_arguments(doc):
    """--size, --spp, --ref-spp and --rounds of an efficiency study."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--ref-spp", type=int, default=1024)
    parser.add_argument("--rounds", type=int, default=3)
    return parser.parse_args()


def efficiency_table(scenes, configs, args, what):
    """Renders each scene's reference once (the default flags, another seed),
    then every configuration, interleaved round by round; prints a Markdown
    table of each one's median relMSE, seconds and efficiency relative to the
    first configuration's. `what` names the configurations' column."""
    size = ["--width", str(args.size), "--height", str(args.size)]
    print(f"{args.size}x{args.size}, {args.spp} spp a render, references at {args.ref_spp} spp; "
          f"medians of {args.rounds} rounds\n")
    print(f"| scene | {what} | relMSE | seconds | efficiency / the first's |")
    print("|---|---|--:|--:|--:|")
    with tempfile.TemporaryDirectory() as tmp:
        cache = os.path.join(tmp, "cache")
        for name, scene in scenes:
            reference = os.path.join(tmp, "reference.exr")
            render(scene, size + ["--spp", str(args.ref_spp), "--seed", "1000"], reference, cache)
            results = {label: [] for label, _ in configs}
            for label, flags in configs:  # compile each program first
                render(scene, size + ["--spp", "1"] + flags, os.path.join(tmp, "warm.exr"), cache)
            for r in range(args.rounds):
                for label, flags in configs:
                    results[label].append(render(scene, size + ["--spp", str(args.spp), "--seed", str(r)] + flags,
                                                 os.path.join(tmp, "out.exr"), cache, ["--reference", reference]))
            base = None
            for label, _ in configs:
                relmse = statistics.median(e for e, _ in results[label])
                seconds = statistics.median(s for _, s in results[label])
                efficiency = 1.0 / (relmse * seconds)
                base = base or efficiency
                print(f"| {name} | {label} | {relmse:.4g} | {seconds:.2f} | {efficiency / base:.2f} |", flush=True)


def main():
    efficiency_table(SCENES, CONFIGS, study_arguments(__doc__), "rule")


if __name__ == "__main__":
    main()
