#!/usr/bin/env python3
"""ray_scaling.py -- how our traversal and our renders slow down as a scene
grows, against how Embree's ray rate slows down on the same scenes (issue
28's scaling target: samples/s may fall no faster than Embree's rate does).

For generated scenes of about 1K, 4K, ... up to --max-triangles triangles
(bench/make_scaling_scene.py: icospheres on a floor under one light, the light
transport the same at every size), one run of build/bench/wavefront_ray_bench
(bounce and shadow rays, ours and Embree's rtcIntersect1 on the same rays and
threads, build times) and one render (build/wavefront --stats-json, after a
1-spp warm-up that compiles the kernels). Every rate is also given relative
to the smallest scene's, so the falls compare directly. Needs bench/setup.sh.

Usage: python3 bench/ray_scaling.py [--max-triangles N] [--rays N] [--spp N]
                                    [--width N] [--out results.md]
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
from throughput import render, rates  # noqa: E402  the renders as the throughput study makes them


def ray_bench(scene, rays, tmp):
    out = os.path.join(tmp, "rays.json")
    subprocess.run([os.path.join(ROOT, "build", "bench", "wavefront_ray_bench"), scene, "--rays", str(rays),
                    "--threads", "2", "--json", out], cwd=ROOT, check=True, capture_output=True, text=True)
    with open(out) as f:
        report = json.load(f)
    sets = {s["set"]: s for s in report["sets"]}
    return report, sets


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--max-triangles", type=int, default=4 << 20)
    parser.add_argument("--rays", type=int, default=200000)
    parser.add_argument("--spp", type=int, default=4)
    parser.add_argument("--width", type=int, default=256)
    parser.add_argument("--out", help="also write the table here (Markdown)")
    args = parser.parse_args()
    if not os.path.exists(os.path.join(ROOT, "build", "bench", "wavefront_ray_bench")):
        sys.exit("ray_scaling.py: build/bench/wavefront_ray_bench is missing: run bench/setup.sh")

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        cache = os.path.join(tmp, "cache")
        triangles = 1 << 10
        while triangles <= args.max_triangles:
            scene = os.path.join(tmp, f"scaling-{triangles}.glb")
            subprocess.run([sys.executable, os.path.join(ROOT, "bench", "make_scaling_scene.py"), str(triangles),
                            scene], check=True, capture_output=True)
            report, sets = ray_bench(scene, args.rays, tmp)
            s = render(scene, ["--width", str(args.width), "--spp", str(args.spp)], cache)
            row = {"triangles": report["triangles"], "build": report["build_seconds"],
                   "embree_build": report["embree_build_seconds"], "bytes": report["bytes_per_triangle"],
                   "samples": rates(s)["msamples_per_s"]}
            for name in ("bounce", "shadow"):
                row[name] = sets[name]["ours_mrays_per_s"]
                row["embree_" + name] = sets[name]["embree_mrays_per_s"]
            rows.append(row)
            device = report["device"]
            print(f"{row['triangles']:8d} triangles: bounce {row['bounce']:.2f} (Embree {row['embree_bounce']:.2f}) "
                  f"Mrays/s, {row['samples']:.3f} M samples/s", flush=True)
            os.remove(scene)
            triangles *= 4

    first = rows[0]
    lines = [f"`python3 bench/ray_scaling.py --max-triangles {args.max_triangles} --rays {args.rays} "
             f"--spp {args.spp} --width {args.width}`; device {device}, Embree on 2 threads. "
             "Rates in M/s; in brackets, relative to the smallest scene.", "",
             "| triangles | build ours / Embree (s) | bytes a triangle | bounce ours | bounce Embree "
             "| shadow ours | shadow Embree | render M samples/s |",
             "|--:|--:|--:|--:|--:|--:|--:|--:|"]
    for r in rows:
        def rel(key):
            return f"{r[key]:.2f} ({r[key] / first[key]:.2f})"
        lines.append(f"| {r['triangles']} | {r['build']:.3f} / {r['embree_build']:.3f} | {r['bytes']:.1f} "
                     f"| {rel('bounce')} | {rel('embree_bounce')} | {rel('shadow')} | {rel('embree_shadow')} "
                     f"| {r['samples']:.3f} ({r['samples'] / first['samples']:.2f}) |")
    last = rows[-1]
    lines += ["", f"From {first['triangles']} to {last['triangles']} triangles: render samples/s fall to "
              f"{last['samples'] / first['samples']:.2f} of the smallest scene's, Embree's bounce rate to "
              f"{last['embree_bounce'] / first['embree_bounce']:.2f} and ours to {last['bounce'] / first['bounce']:.2f}."]
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
