#!/usr/bin/env python3
"""mpi_scaling.py -- issue 17's scaling figures on one machine: one process
with one PoCL thread against two MPI ranks of one thread each (ideal 2x), two
PoCL devices of one thread in one process (the same split without MPI), and
one process with every core (PoCL's own threads, for reference). Rates are
samples over the render's wall time from `--stats-json`; the whole command's
wall time (MPI's start, every rank's scene load and kernel build) is given
too. The cost of gathering the film is the devices' time moving their units'
sums (to and from the device, and between ranks) over their busy time. Runs
are interleaved round by round so that the machine's load falls on all alike;
each setup renders 1 spp first so that PoCL's kernels are compiled.

Usage: python3 bench/mpi_scaling.py [--rounds N] [--width N]
       (from any directory; needs a build with MPI: scripts/setup.sh)
"""

import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

from throughput import REAL, ROOT

SCENES = [  # name, path from the repository root, spp
    ("Cornell box", "scenes/cornell-box.gltf", 32),
    ("ToyCar (109 K triangles, textured)", REAL + "ToyCar/ToyCar.gltf", 16),
]
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}
CONFIGS = [  # label, command prefix, extra environment, extra flags
    ("1 process x 1 thread", [], {"POCL_MAX_PTHREAD_COUNT": "1"}, []),
    ("2 ranks x 1 thread", ["mpirun", "--oversubscribe", "-np", "2"], {"POCL_MAX_PTHREAD_COUNT": "1", **MPI_ENV}, []),
    ("2 devices x 1 thread", [], {"POCL_MAX_PTHREAD_COUNT": "1", "POCL_DEVICES": "pthread pthread"},
     ["--device", "all"]),
    ("1 process x 2 threads", [], {}, []),
]


def run(prefix, env, flags, scene, spp, width, cache):
    """One render; its statistics and the command's wall time."""
    with tempfile.TemporaryDirectory() as tmp:
        stats = os.path.join(tmp, "stats.json")
        command = prefix + ["build/wavefront", "render", scene, "-o", os.path.join(tmp, "out.exr"), "--seed", "1",
                            "--width", str(width), "--height", str(width), "--spp", str(spp), "--cache-dir", cache,
                            "--stats-json", stats] + flags
        start = time.monotonic()
        subprocess.run(command, cwd=ROOT, env={**os.environ, **env}, check=True, capture_output=True, text=True)
        wall = time.monotonic() - start
        with open(stats) as f:
            return json.load(f), wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--width", type=int, default=512)
    args = parser.parse_args()
    print("| scene | setup | M samples/s (each round) | x 1 thread | command wall s | "
          "moving sums / busy | each device's share |")
    print("|---|---|---|--:|--:|--:|---|")
    with tempfile.TemporaryDirectory() as cache:
        for name, scene, spp in SCENES:
            results = {label: [] for label, *_ in CONFIGS}
            for label, prefix, env, flags in CONFIGS:
                run(prefix, env, flags, scene, 1, args.width, cache)  # compile
            for _ in range(args.rounds):
                for label, prefix, env, flags in CONFIGS:
                    results[label].append(run(prefix, env, flags, scene, spp, args.width, cache))
            base = statistics.median(s["samples"] / s["times"]["render"] for s, _ in results[CONFIGS[0][0]])
            for label, *_ in CONFIGS:
                rates = [s["samples"] / s["times"]["render"] * 1e-6 for s, _ in results[label]]
                walls = [w for _, w in results[label]]
                last = results[label][-1][0]
                shares = last.get("device_shares", [])
                moving = sum(d["transfer_seconds"] for d in shares)
                busy = sum(d["busy_seconds"] for d in shares)
                split = ", ".join(f"{100.0 * d['samples'] / last['samples']:.0f}%" for d in shares) or "-"
                gather = f"{100.0 * moving / busy:.1f}%" if busy else "-"
                print(f"| {name}, {args.width}², {spp} spp | {label} | {', '.join(f'{r:.3f}' for r in rates)} | "
                      f"{statistics.median(rates) * 1e6 / base:.2f} | {statistics.median(walls):.1f} | {gather} | "
                      f"{split} |", flush=True)


if __name__ == "__main__":
    main()
