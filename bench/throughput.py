#!/usr/bin/env python3
"""throughput.py -- where the time goes (issue 7): renders a scene set with
each integrator and schedule, sweeps the pool and local sizes, and times the
kernel build cold and warm. Every figure comes from `wavefront render
--stats-json` (OpenCL profiling events and the device's counters). Writes
bench/results/throughput.json (every run's statistics but the per-iteration
counters), throughput.md (the tables) and throughput-*.png (the plots). The
scaling table renders generated scenes of 1K to 4M triangles
(bench/make_scaling_scene.py, written to a temporary folder) and the Cornell
box at several resolutions.

Usage: python3 bench/throughput.py [--size N] [--spp N] [--sweep-size N] [--max-triangles N]
       (from any directory; needs python3-numpy and python3-matplotlib; about
       15 minutes on 2 cores)
"""

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "bench", "results")
REAL = "../shared/scenes-real/"
SCENES = [  # name, path from the repository root, extra flags
    ("Cornell box", "scenes/cornell-box.gltf", []),
    ("glossy teapot", "scenes/cornell-teapot.gltf", []),
    ("glass sphere", "scenes/cornell-glass.gltf", []),
    ("DamagedHelmet", REAL + "DamagedHelmet/DamagedHelmet.glb", ["--env-uniform", "1"]),
    ("TransmissionTest", REAL + "TransmissionTest/TransmissionTest.gltf", []),
    ("MetalRoughSpheresNoTextures", REAL + "MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf", []),
]
CONFIGS = [  # label, flags
    ("wavefront, refill", ["--schedule", "refill"]),
    ("wavefront, passes", ["--schedule", "passes"]),
    ("wavefront, fullest", ["--schedule", "fullest"]),
    ("wavefront, group", ["--schedule", "group"]),  # a CPU's default: every stage inside each work-group
    ("megakernel", ["--integrator", "megakernel"]),
]
BUILD_CONFIGS = [CONFIGS[0], CONFIGS[3], CONFIGS[4]]  # refill, group, megakernel: one program each


def render(scene, flags, cache, pocl_cache=None, warm_up=True):
    """One render; returns its --stats-json statistics. PoCL compiles each
    kernel for its launch at first use, inside the render's time, so unless
    the build itself is measured a 1-spp render of the same setup goes first."""
    if warm_up:
        render(scene, [f if flags[i - 1] != "--spp" else "1" for i, f in enumerate(flags)], cache, pocl_cache, False)
    env = dict(os.environ)
    if pocl_cache:
        env["POCL_CACHE_DIR"] = pocl_cache
    with tempfile.TemporaryDirectory() as tmp:
        stats = os.path.join(tmp, "stats.json")
        command = ["build/wavefront", "render", scene, "-o", os.path.join(tmp, "out.exr"), "--seed", "1",
                   "--cache-dir", cache, "--stats-json", stats] + flags
        subprocess.run(command, cwd=ROOT, env=env, check=True, capture_output=True, text=True)
        with open(stats) as f:
            return json.load(f)


def rates(s):
    """The figures a row of the tables shows."""
    stages = s["stages"]
    seconds = s["times"]["render"]
    def kernel(name):
        return stages.get(name, {}).get("seconds", 0.0)
    closest_kernel = kernel("intersect") or kernel("megakernel") or kernel("group_wavefront")
    shadow_kernel = kernel("intersect_shadow")
    return {
        "msamples_per_s": s["samples"] / seconds * 1e-6,
        "closest_mrays_per_s_wall": s["closest_rays"] / seconds * 1e-6,
        "closest_mrays_per_s_kernel": s["closest_rays"] / closest_kernel * 1e-6 if closest_kernel else 0.0,
        # None where no kernel traces shadow rays alone (the megakernel's and the group's do it all)
        "shadow_mrays_per_s_kernel": s["shadow_rays"] / shadow_kernel * 1e-6 if shadow_kernel else None,
        "host_share": (seconds - s["times"]["kernels"]) / seconds,
        "occupancy": s["pool_occupancy"],
        "iterations": s["iterations"],
        "bytes_per_path": s["memory"]["bytes_per_path"],
        "traversal_bytes_per_triangle": s["memory"]["traversal_bytes_per_triangle"],
        "stage_seconds": {k: v["seconds"] for k, v in stages.items()},
        "render_seconds": seconds,
        "schedule": s["integrator"] if s["integrator"] == "megakernel" else s["schedule"],
    }


def rate(x):
    """A rate's cell: two decimals, or a dash where there is none."""
    return "—" if x is None else f"{x:.2f}"


def without_counters(s):
    return {k: v for k, v in s.items() if k not in ("counter_reads", "counter_read_columns")}


def plot_queues(runs, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(runs), 1, figsize=(9, 2.4 * len(runs)), sharex=False)
    for ax, (label, s) in zip(axes, runs):
        columns = s["counter_read_columns"]
        reads = s["counter_reads"]
        for name in ("closest_rays", "shadow_rays", "samples"):
            i = columns.index(name)
            ax.plot([r[i] for r in reads], label=name, linewidth=0.8)
        ax.set_title(f"{label}: {len(reads)} counter reads, occupancy {100 * s['pool_occupancy']:.0f}%", fontsize=9)
        ax.set_ylabel("paths")
        ax.legend(fontsize=7, loc="upper right")
    axes[-1].set_xlabel("counter read (iteration, or step for fullest)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def plot_sweep(xs, ys, xlabel, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(xs, ys, "o-")
    ax.set_xscale("log", base=2)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("M samples/s")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=256, help="image width for the scene set")
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--sweep-size", type=int, default=2048, help="image width of the pool sweep")
    parser.add_argument("--max-triangles", type=int, default=1 << 22, help="largest generated scene")
    args = parser.parse_args()
    os.makedirs(RESULTS, exist_ok=True)
    cache = tempfile.mkdtemp(prefix="wavefront-cache-")
    base = ["--width", str(args.size), "--spp", str(args.spp)]
    out = {"machine": platform.processor() or platform.machine(), "size": args.size, "spp": args.spp,
           "builds": [], "scenes": [], "pool_sweep": [], "local_sweep": [], "push_sweep": [],
           "triangle_scaling": [], "resolution_scaling": []}
    md = []

    # Kernel build, cold (empty program and PoCL caches) then warm.
    for name, scene, extra in SCENES[:2]:
        for label, flags in BUILD_CONFIGS:
            pocl = tempfile.mkdtemp(prefix="pocl-")
            cold_cache = tempfile.mkdtemp(prefix="wavefront-cold-")
            small = ["--width", "16", "--spp", "1"] + extra + flags
            cold = render(scene, small, cold_cache, pocl, warm_up=False)["times"]["kernel_build"]
            warm = render(scene, small, cold_cache, pocl, warm_up=False)["times"]["kernel_build"]
            out["builds"].append({"scene": name, "integrator": label, "cold": cold, "warm": warm})

    # The scene set, every integrator and schedule.
    queue_runs = []
    for name, scene, extra in SCENES:
        for label, flags in CONFIGS:
            s = render(scene, base + extra + flags, cache)
            out["scenes"].append({"scene": name, "config": label, "triangles": s["triangles"],
                                  "device": s["device"], **rates(s), "stats": without_counters(s)})
            if name == "Cornell box":
                queue_runs.append((label, s))
            print(f"{name:28s} {label:20s} {out['scenes'][-1]['msamples_per_s']:.3f} M samples/s", flush=True)
    plot_queues(queue_runs, os.path.join(RESULTS, "throughput-queues.png"))

    # Pool sizes, Cornell box, one image large enough for the largest pool.
    pools = [1 << 14, 1 << 16, 1 << 18, 1 << 20, 1 << 22]
    for pool in pools:
        if pool > args.sweep_size * args.sweep_size:
            continue
        s = render("scenes/cornell-box.gltf", ["--width", str(args.sweep_size), "--spp", "2", "--pool-size",
                                               str(pool)], cache)
        out["pool_sweep"].append({"pool": pool, **rates(s), "device_bytes": s["memory"]["device_bytes"]})
        print(f"pool {pool:8d} {out['pool_sweep'][-1]['msamples_per_s']:.3f} M samples/s", flush=True)
    plot_sweep([r["pool"] for r in out["pool_sweep"]], [r["msamples_per_s"] for r in out["pool_sweep"]],
               f"pool size (paths), Cornell box {args.sweep_size}x{args.sweep_size}, 2 spp",
               os.path.join(RESULTS, "throughput-pool.png"))

    # Local sizes, Cornell box, the scene set's image.
    for local in (16, 32, 64, 128, 256):
        s = render("scenes/cornell-box.gltf", base + ["--local-size", str(local)], cache)
        out["local_sweep"].append({"local_size": local, **rates(s)})

    # Queue-push strategies, Cornell box, on the refill schedule: the group
    # schedule (a CPU's default) pushes to local queues, not through these.
    for push in ("group", "atomic", "scan", "serial"):
        s = render("scenes/cornell-box.gltf", base + ["--schedule", "refill", "--queue-push", push], cache)
        out["push_sweep"].append({"queue_push": push, **rates(s)})

    # Triangle count: generated scenes, 1K to 4M triangles.
    with tempfile.TemporaryDirectory() as tmp:
        triangles = 1 << 10
        while triangles <= args.max_triangles:
            scene = os.path.join(tmp, f"scaling-{triangles}.glb")
            subprocess.run([sys.executable, os.path.join(ROOT, "bench", "make_scaling_scene.py"), str(triangles),
                            scene], check=True, capture_output=True)
            s = render(scene, base, cache)
            out["triangle_scaling"].append({"triangles": s["triangles"], "bvh_build": s["times"]["bvh_build"],
                                            "load": s["times"]["load"], **rates(s)})
            print(f"{s['triangles']:8d} triangles {out['triangle_scaling'][-1]['msamples_per_s']:.3f} M samples/s",
                  flush=True)
            os.remove(scene)
            triangles *= 4

    # Resolution, Cornell box.
    for width in (128, 256, 512, 1024):
        s = render("scenes/cornell-box.gltf", ["--width", str(width), "--spp", str(args.spp)], cache)
        out["resolution_scaling"].append({"width": width, "height": s["height"], **rates(s)})

    device = out["scenes"][0]["device"]
    md.append("# Throughput: integrators, schedules, pool and local sizes\n")
    md.append(f"`python3 bench/throughput.py --size {args.size} --spp {args.spp} --sweep-size {args.sweep_size}` "
              f"on {device}. Samples/s are end to end (render wall time, rounds at each doubling of spp "
              "included); ray rates are over the intersect kernels' own time (for the megakernel and the group "
              "schedule, over the whole kernel, which also shades). Host share: wall time outside kernels.\n")
    md.append("## Kernel build\n\n| scene | integrator | cold (s) | warm (s) |\n|---|---|--:|--:|")
    for b in out["builds"]:
        md.append(f"| {b['scene']} | {b['integrator']} | {b['cold']:.2f} | {b['warm']:.3f} |")
    md.append(f"\n## Scenes, {args.size} wide, {args.spp} spp\n")
    md.append("| scene | triangles | integrator, schedule | M samples/s | closest Mrays/s (kernel) | "
              "shadow Mrays/s (kernel) | host share | pool occupancy | counter reads | bytes/path | "
              "BVH+triangles bytes/triangle |")
    md.append("|---|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|")
    for r in out["scenes"]:
        md.append(f"| {r['scene']} | {r['triangles']} | {r['config']} | {r['msamples_per_s']:.3f} | "
                  f"{r['closest_mrays_per_s_kernel']:.2f} | {rate(r['shadow_mrays_per_s_kernel'])} | "
                  f"{100 * r['host_share']:.1f}% | {100 * r['occupancy']:.0f}% | {r['iterations']} | "
                  f"{r['bytes_per_path']} | {r['traversal_bytes_per_triangle']:.1f} |")
    md.append("\n## Stage times (s), wavefront refill\n")
    stage_names = ["generate", "intersect", "shade", "intersect_shadow", "roulette", "accumulate"]
    md.append("| scene | " + " | ".join(stage_names) + " |\n|---|" + "--:|" * len(stage_names))
    for r in out["scenes"]:
        if r["config"] == CONFIGS[0][0]:
            md.append(f"| {r['scene']} | " + " | ".join(f"{r['stage_seconds'].get(n, 0.0):.3f}"
                                                      for n in stage_names) + " |")
    md.append("\n![queues](throughput-queues.png)\n")
    md.append(f"## Pool size, Cornell box {args.sweep_size}x{args.sweep_size}, 2 spp, "
              f"{out['pool_sweep'][0]['schedule']} (the device's default)\n")
    md.append("| pool | M samples/s | host share | occupancy | device MiB |\n|--:|--:|--:|--:|--:|")
    for r in out["pool_sweep"]:
        md.append(f"| {r['pool']} | {r['msamples_per_s']:.3f} | {100 * r['host_share']:.1f}% | "
                  f"{100 * r['occupancy']:.0f}% | {r['device_bytes'] / 2**20:.0f} |")
    md.append("\n![pool](throughput-pool.png)\n")
    md.append(f"## Local size, Cornell box {args.size} wide, {args.spp} spp, "
              f"{out['local_sweep'][0]['schedule']} (the device's default)\n")
    md.append("| local size | M samples/s | closest Mrays/s (kernel) | shadow Mrays/s (kernel) |\n|--:|--:|--:|--:|")
    for r in out["local_sweep"]:
        md.append(f"| {r['local_size']} | {r['msamples_per_s']:.3f} | {r['closest_mrays_per_s_kernel']:.2f} | "
                  f"{rate(r['shadow_mrays_per_s_kernel'])} |")
    md.append(f"\n## Queue-push strategy, Cornell box {args.size} wide, {args.spp} spp, refill schedule\n")
    pushing = ("shade", "intersect_shadow", "roulette", "accumulate", "generate")  # the stages that push
    md.append("| strategy | M samples/s | " + " | ".join(f"{k} (s)" for k in pushing) + " |\n|---|--:|" +
              "--:|" * len(pushing))
    for r in out["push_sweep"]:
        st = r["stage_seconds"]
        md.append(f"| {r['queue_push']} | {r['msamples_per_s']:.3f} | " +
                  " | ".join(f"{st.get(k, 0):.3f}" for k in pushing) + " |")
    md.append(f"\n## Triangle count, generated scenes, {args.size} wide, {args.spp} spp, "
              f"{out['triangle_scaling'][0]['schedule']} (the device's default)\n")
    md.append("| triangles | load (s) | BVH build (s) | render (s) | M samples/s | closest Mrays/s (kernel) | "
              "shadow Mrays/s (kernel) | BVH+triangles bytes/triangle |\n|--:|--:|--:|--:|--:|--:|--:|--:|")
    for r in out["triangle_scaling"]:
        md.append(f"| {r['triangles']} | {r['load']:.2f} | {r['bvh_build']:.2f} | {r['render_seconds']:.2f} | "
                  f"{r['msamples_per_s']:.3f} | {r['closest_mrays_per_s_kernel']:.2f} | "
                  f"{rate(r['shadow_mrays_per_s_kernel'])} | {r['traversal_bytes_per_triangle']:.1f} |")
    md.append(f"\n## Resolution, Cornell box, {args.spp} spp, "
              f"{out['resolution_scaling'][0]['schedule']} (the device's default)\n")
    md.append("| image | render (s) | M samples/s | host share |\n|---|--:|--:|--:|")
    for r in out["resolution_scaling"]:
        md.append(f"| {r['width']}x{r['height']} | {r['render_seconds']:.2f} | {r['msamples_per_s']:.3f} | "
                  f"{100 * r['host_share']:.1f}% |")
    with open(os.path.join(RESULTS, "throughput.json"), "w") as f:
        json.dump(out, f, indent=1)
    with open(os.path.join(RESULTS, "throughput.md"), "w") as f:
        f.write("\n".join(md) + "\n")


if __name__ == "__main__":
    main()
