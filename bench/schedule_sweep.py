#!/usr/bin/env python3
"""schedule_sweep.py -- a scheduling study through the Python module (issue
18): every wavefront schedule x pool size x local size on two scenes, the
samples a second of each, and the queue lengths over the iterations of one
render per schedule, as the module returns them (no output is parsed).
Writes bench/results/schedule-sweep.md and two plots beside it:
schedule-sweep-rates.png (samples/s against the pool size, a line per
schedule and local size, a panel per scene) and schedule-sweep-queues.png
(each queue's length at every read of the counters).

Usage: python3 bench/schedule_sweep.py [--width N] [--spp N]
       (from any directory, after scripts/setup.sh; about 10 minutes on 2 cores)
"""

import argparse
import os
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import wavefront  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "bench", "results")
SCENES = [
    ("Cornell box", os.path.join(ROOT, "scenes", "cornell-box.gltf")),
    ("MetalRoughSpheresNoTextures", os.path.join(ROOT, "..", "shared", "scenes-real", "MetalRoughSpheresNoTextures",
                                                 "MetalRoughSpheresNoTextures.gltf")),
]
SCHEDULES = ["refill", "passes", "fullest", "group"]
POOLS = [4096, 16384, 65536]
LOCAL_SIZES = [32, 64, 128]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--width", type=int, default=256)
    parser.add_argument("--spp", type=int, default=4)
    args = parser.parse_args()
    size = dict(width=args.width, height=args.width, spp=args.spp, seed=1)
    rates = {}   # (scene, schedule, local size) -> [M samples/s by pool]
    queues = {}  # (scene, schedule) -> counter reads of one render
    with tempfile.TemporaryDirectory() as cache:
        for name, path in SCENES:
            scene = wavefront.load_scene(path)
            for schedule in SCHEDULES:
                for local in LOCAL_SIZES:
                    row = []
                    for pool in POOLS:
                        flags = dict(schedule=schedule, pool_size=pool, local_size=local, cache_dir=cache)
                        wavefront.render(scene, **flags, **dict(size, spp=1))  # PoCL compiles at first launch
                        result = wavefront.render(scene, **flags, **size)
                        row.append(result.stats.samples / result.stats.seconds * 1e-6)
                        if local == 64 and pool == 65536:
                            queues[name, schedule] = result.stats.counter_reads
                    rates[name, schedule, local] = row
                    print(name, schedule, local, " ".join(f"{r:.3f}" for r in row), flush=True)

    figure, panels = plt.subplots(1, len(SCENES), figsize=(12, 4.5), sharey=False)
    for panel, (name, _) in zip(panels, SCENES):
        for schedule in SCHEDULES:
            for local, style in zip(LOCAL_SIZES, [":", "-", "--"]):
                panel.plot(POOLS, rates[name, schedule, local], style, marker="o",
                           color=f"C{SCHEDULES.index(schedule)}", label=f"{schedule}, local {local}")
        panel.set_xscale("log", base=2)
        panel.set(title=name, xlabel="pool size (paths)", ylabel="M samples/s")
    panels[0].legend(fontsize=7, ncol=2)
    figure.tight_layout()
    figure.savefig(os.path.join(RESULTS, "schedule-sweep-rates.png"), dpi=110)

    columns = wavefront.Stats.counter_read_columns
    figure, panels = plt.subplots(len(SCENES), len(SCHEDULES), figsize=(14, 6), sharex=False)
    for r, (name, _) in enumerate(SCENES):
        for c, schedule in enumerate(SCHEDULES):
            reads = queues[name, schedule]
            for q in range(5):
                panels[r][c].plot(reads[:, q], label=columns[q], linewidth=0.8)
            panels[r][c].set(title=f"{name}: {schedule}", xlabel="counter read")
    panels[0][0].legend(fontsize=7)
    figure.suptitle(f"Queue lengths as read, pool 65536, local size 64, {args.width}², {args.spp} spp")
    figure.tight_layout()
    figure.savefig(os.path.join(RESULTS, "schedule-sweep-queues.png"), dpi=110)

    lines = ["# Schedule × pool size × local size, through the Python module", "",
             f"`python3 bench/schedule_sweep.py --width {args.width} --spp {args.spp}`, on "
             f"{wavefront.devices()[0].name} (PoCL), the default device. M samples/s over the render's "
             "wall time, from `Result.stats`; kernels compiled by a 1-spp render first. "
             "Plots: [rates](schedule-sweep-rates.png), [queue lengths](schedule-sweep-queues.png) (the group "
             "schedule keeps its queues in each work-group's local memory: its global counters stay 0).", "",
             "| scene | schedule | local size | " + " | ".join(f"pool {p}" for p in POOLS) + " |",
             "|---|---|--:|" + "--:|" * len(POOLS)]
    for name, _ in SCENES:
        for schedule in SCHEDULES:
            for local in LOCAL_SIZES:
                lines.append(f"| {name} | {schedule} | {local} | " +
                             " | ".join(f"{r:.3f}" for r in rates[name, schedule, local]) + " |")
    with open(os.path.join(RESULTS, "schedule-sweep.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
