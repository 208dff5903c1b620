#!/usr/bin/env python3
"""gpu.py -- the prepared GPU run (issue 29): on a machine with an OpenCL GPU,
in a few minutes, what the renderer does there and how fast, written to
OUT/gpu-run.md and OUT/gpu-run.json with the device named.

    bench/gpu.sh [--out DIR] [--bin DIR] [--real DIR] [--budget SECONDS] [--references DIR]

In order of what matters most, each step skipped once the budget is spent:
  1. `wavefront devices` (and the start-up layout check) on the GPU;
  2. correctness: the Cornell box and three more scenes at 256 wide, 16 spp,
     seed 1, with each integrator. The wavefront and the megakernel must give
     the same pixels (relMSE 0); against CPU renders of the same seed made
     beforehand (--make-references DIR, on a CPU device), relMSE is printed
     beside that of an independent CPU render (seed 2), the noise's own scale;
  3. throughput: 1024-wide renders for --time seconds after a 1-spp warm-up
     that compiles the program (the first compile of each is timed too):
     the wavefront (its GPU schedule) and the megakernel on six scenes, then
     the Cornell box under every schedule, pool size, local size, queue
     push and shade in one kernel or two (--only knobs: the last alone,
     beside the default);
     (--only traversal: the ray bench with a GPU's kernels and with a CPU's);
  4. wavefront_ray_bench --device gpu on three scenes (our kernels on the GPU,
     Embree on every host core, the same rays).
Only the standard library; the programs are --bin's (default build/, and
build/bench/ for the ray bench; a bench/portable_bundle.py bundle's bin/).
Where the OpenCL loader lists no GPU but a GPU driver's library is on disk
(a container given NVIDIA's libraries without /etc/OpenCL/vendors, as on the
machines lent here), the run names it to the loader itself (OCL_ICD_VENDORS,
OCL_ICD_FILENAMES) and says so.
"""

import argparse
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHECK_SCENES = [  # name, path (scene-relative to the repository or --real), extra flags
    ("Cornell box", "scenes/cornell-box.gltf", []),
    ("glass sphere", "scenes/cornell-glass.gltf", []),
    ("glossy teapot", "scenes/cornell-teapot.gltf", []),
    ("MetalRoughSpheresNoTextures", "real:MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf", []),
]
SPEED_SCENES = CHECK_SCENES + [
    ("ToyCar", "real:ToyCar/ToyCar.gltf", []),
    ("DamagedHelmet", "real:DamagedHelmet/DamagedHelmet.glb", ["--env-uniform", "1"]),
]
RAY_SCENES = ["scenes/cornell-box.gltf", "real:MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf",
              "real:ToyCar/ToyCar.gltf"]
CHECK_FLAGS = ["--width", "256", "--spp", "16"]  # the checks' renders and their CPU references alike
INTEGRATORS = [("wavefront", []), ("megakernel", ["--integrator", "megakernel"])]
SCHEDULES = [("passes", ["--schedule", "passes"]),  # the wavefront rows above are refill, a GPU's default
             ("fullest", ["--schedule", "fullest"]), ("refill, sorted", ["--schedule", "refill", "--sort-materials"])]
# GPU drivers' OpenCL libraries, and where containers and packages put them.
DRIVER_LIBRARIES = ["libnvidia-opencl.so.1", "libamdocl64.so", "libigdrcl.so"]
DRIVER_DIRS = ["/usr/local/nvidia/lib64", "/usr/lib/x86_64-linux-gnu", "/usr/lib64", "/opt/rocm/lib",
               "/usr/lib/x86_64-linux-gnu/intel-opencl"]
KNOBS = [("local size 32", ["--local-size", "32"]), ("local size 128", ["--local-size", "128"]),
         ("local size 256", ["--local-size", "256"]), ("queue push atomic", ["--queue-push", "atomic"]),
         ("queue push scan", ["--queue-push", "scan"]), ("group schedule", ["--schedule", "group"]),
         ("one shade kernel", ["--shade-kernels", "1"]),
         ("megakernel, local size 128", ["--integrator", "megakernel", "--local-size", "128"])]
POOLS = [262144, 1048576, 4194304]  # at most the pixels: these rows render 2048 wide


class Run:
    def __init__(self, args):
        self.args = args
        self.deadline = time.monotonic() + args.budget
        self.log = open(os.path.join(args.out, "gpu-run.log"), "a")
        self.tmp = tempfile.mkdtemp(prefix="wf-gpu-")
        self.env = dict(os.environ, XDG_CACHE_HOME=os.path.join(self.tmp, "cache"))
        self.data = {"machine": {"host": platform.node(), "cpu": cpu_name(), "cores": os.cpu_count()},
                     "device": None, "checks": [], "builds": [], "speed": [], "rays": [], "skipped": []}

    def left(self):
        return self.deadline - time.monotonic()

    def scene(self, path):
        return scene_path(self.args.real, path)

    def program(self, name):
        for d in (self.args.bin, os.path.join(self.args.bin, "bench")):
            if os.path.exists(os.path.join(d, name)):
                return os.path.join(d, name)
        sys.exit(f"gpu.py: no {name} under {self.args.bin}")

    def call(self, what, command, limit=150):
        """Runs command, logged; returns it completed, or None (failed, timed out or out of budget)."""
        if self.left() < 10:
            self.data["skipped"].append(what)
            return None
        start = time.monotonic()
        self.log.write(f"\n$ {' '.join(command)}\n")
        self.log.flush()
        try:
            done = subprocess.run(command, env=self.env, capture_output=True, text=True,
                                  timeout=min(limit, self.left()))
        except subprocess.TimeoutExpired as e:
            self.log.write(f"[timed out after {time.monotonic() - start:.0f} s]\n{e.stdout or ''}{e.stderr or ''}")
            self.data["skipped"].append(what + " (timed out)")
            return None
        self.log.write(done.stdout + done.stderr + f"[exit {done.returncode}, {time.monotonic() - start:.1f} s]\n")
        self.log.flush()
        if done.returncode != 0:
            self.data["skipped"].append(f"{what} (exit {done.returncode}: {last_line(done.stderr)})")
            return None
        return done

    def render(self, what, scene, flags, out="out.exr", limit=150):
        stats = os.path.join(self.tmp, "stats.json")
        command = [self.program("wavefront"), "render", self.scene(scene), "-o", os.path.join(self.tmp, out),
                   "--device", self.args.device, "--stats-json", stats, "--quiet"] + flags
        if self.call(what, command, limit) is None:
            return None
        with open(stats) as f:
            s = json.load(f)
        if not s["times"]["kernels_from_cache"]:  # the first render of a program compiled it
            self.data["builds"].append({"scene": what.split(" ", 1)[1], "integrator": s["integrator"],
                                        "schedule": s["schedule"], "features": s["features"],
                                        "seconds": s["times"]["kernel_build"]})
        return s

    def save(self):
        with open(os.path.join(self.args.out, "gpu-run.json"), "w") as f:
            json.dump(self.data, f, indent=1)
        with open(os.path.join(self.args.out, "gpu-run.md"), "w") as f:
            f.write(markdown(self.data))


def scene_path(real, scene):
    """A scene of the lists above: "real:X" under --real, else under the repository."""
    return os.path.join(real, scene[5:]) if scene.startswith("real:") else os.path.join(ROOT, scene)


def reference_path(references, scene, seed):
    """Where --make-references puts the CPU render of `scene` at `seed`."""
    return os.path.join(references, os.path.basename(scene).split(".")[0] + f"-seed{seed}.exr")


def cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            return next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        return platform.processor()


def last_line(text):
    lines = [l for l in text.strip().splitlines() if l.strip()]
    return lines[-1][:200] if lines else ""


def relmse(run, what, scene, flags, image, reference):
    """relMSE of a render's image against `reference`, from its --report CSV."""
    csv = os.path.join(run.tmp, "report.csv")
    if run.render(what, scene, flags + ["--reference", reference, "--report", csv], image) is None:
        return None
    with open(csv) as f:
        return float(f.read().strip().splitlines()[-1].split(",")[3])


def register_unlisted_drivers(run):
    """Names the GPU drivers found on disk to the OpenCL loader, in a folder of
    .icd files of the run's own; False if there is none."""
    found = [os.path.join(d, n) for d in DRIVER_DIRS for n in DRIVER_LIBRARIES if os.path.exists(os.path.join(d, n))]
    if not found:
        return False
    icd = os.path.join(run.tmp, "icd")
    os.makedirs(icd, exist_ok=True)
    for i, library in enumerate(found):
        with open(os.path.join(icd, f"{i}.icd"), "w") as f:
            f.write(library + "\n")
    dirs = sorted({os.path.dirname(f) for f in found})
    run.env.update(OCL_ICD_VENDORS=icd, OCL_ICD_FILENAMES=":".join(found),
                   WF_EXTRA_LIBRARY_PATH=":".join(dirs))  # for a portable bundle's own loader
    run.log.write(f"\n[no GPU listed; named to the loader: {', '.join(found)}]\n")
    return True


def check_step(run, name, scene, extra):
    base = CHECK_FLAGS + ["--seed", "1"] + extra
    row = {"scene": name}
    wave = os.path.join(run.tmp, "wavefront.exr")
    s = run.render(f"check {name} wavefront", scene, base, wave)
    if s is None:
        return
    row["nonfinite_samples"] = s["nonfinite_samples"]
    row["wavefront_vs_megakernel"] = relmse(run, f"check {name} megakernel", scene,
                                            base + ["--integrator", "megakernel"], "mega.exr", wave)
    refs = run.args.references
    if refs and os.path.exists(reference_path(refs, scene, 1)):
        row["gpu_vs_cpu_same_seed"] = relmse(run, f"check {name} vs cpu", scene, base, "same.exr",
                                             reference_path(refs, scene, 1))
        row["cpu_vs_cpu_other_seed"] = relmse(run, f"check {name} vs cpu seed 2", scene, base, "other.exr",
                                              reference_path(refs, scene, 2))
    run.data["checks"].append(row)
    run.save()


def speed_row(run, label, name, scene, flags, width=1024):
    seconds = run.args.seconds
    warm = run.render(f"warm-up {name} {label}", scene, ["--width", "64", "--spp", "1"] + flags)
    if warm is None:
        return
    s = run.render(f"speed {name} {label}", scene,
                   ["--width", str(width), "--spp", "65536", "--time", str(seconds), "--seed", "1"] + flags,
                   limit=seconds * 4 + 60)
    if s is None:
        return
    render = s["times"]["render"]
    stages = s["stages"]
    closest = sum(v["seconds"] for k, v in stages.items() if k.startswith("intersect") and "shadow" not in k)
    run.data["speed"].append({
        "scene": name, "config": label, "triangles": s["triangles"], "spp": s["spp"], "seconds": render,
        "msamples_per_s": s["samples"] / render * 1e-6,
        "mrays_per_s": (s["closest_rays"] + s["shadow_rays"]) / render * 1e-6,
        "closest_mrays_per_s_kernel": s["closest_rays"] / closest * 1e-6 if closest else None,
        "host_share": (render - s["times"]["kernels"]) / render, "pool_size": s["pool_size"],
        "schedule": s["schedule"], "integrator": s["integrator"], "features": s["features"],
        "stage_seconds": {k: v["seconds"] for k, v in stages.items()}})
    run.save()


def ray_step(run, scene, kernels="auto"):
    out = os.path.join(run.tmp, "rays.json")
    done = run.call(f"rays {scene} ({kernels} kernels)",
                    [run.program("wavefront_ray_bench"), run.scene(scene), "--device", run.args.device, "--kernels",
                     kernels, "--rays", str(run.args.rays), "--threads", str(os.cpu_count()), "--json", out], limit=240)
    if done is not None:
        with open(out) as f:
            run.data["rays"].append(dict(json.load(f), kernels=kernels))
        run.save()


def registers(log_path):
    """Per kernel of each distinct program: registers, stack frame, spills and
    shared memory, from NVIDIA's -cl-nv-verbose report in a WF_KERNEL_BUILD_LOG."""
    rows, seen, program, kernel = [], set(), None, None
    with open(log_path, errors="replace") as f:
        for line in f:
            if line.startswith("== "):
                root, _, options = line[3:].partition(": ")
                on = [o[9:-2].lower() for o in options.split() if o.startswith("-DWF_HAS_") and o.endswith("=1")]
                key = (root.split(" on ")[0], " ".join(sorted(set(options.split()))))
                program = None if key in seen else f"{key[0]} ({', '.join(on) or 'no features'})"
                seen.add(key)
            elif program and (m := re.search(r"Compiling entry function '(\w+)'", line)):
                kernel = {"program": program, "kernel": m.group(1)}
            elif program and kernel and (m := re.search(r"(\d+) bytes stack frame, (\d+) bytes spill stores", line)):
                kernel["stack"], kernel["spill_stores"] = int(m.group(1)), int(m.group(2))
            elif program and kernel and (m := re.search(r"Used (\d+) registers", line)):
                smem = re.search(r"(\d+) bytes smem", line)
                kernel.update(registers=int(m.group(1)), smem=int(smem.group(1)) if smem else 0)
                rows.append(kernel)
                kernel = None
    return [r for r in rows if not r["program"].startswith("layout_probe")]


def markdown(d):
    dev = d["device"] or "(no GPU found)"
    m = d["machine"]
    lines = [f"# GPU run: {dev}", "",
             f"`bench/gpu.sh` on {m['host']}: {m['cpu']}, {m['cores']} cores (Embree's threads). "
             "Everything below is one run of the script.", ""]
    if d["checks"]:
        lines += ["## Correctness (256 wide, 16 spp, seed 1)", "",
                  "relMSE of the GPU's wavefront image against: the GPU's megakernel (same bytes: 0), a CPU render "
                  "of the same seed, and, for scale, a CPU render of another seed.", "",
                  "| scene | megakernel | CPU, same seed | CPU, seed 2 | non-finite samples |", "|---|--:|--:|--:|--:|"]
        for c in d["checks"]:
            f = lambda k: "-" if c.get(k) is None else f"{c[k]:.3g}"
            lines.append(f"| {c['scene']} | {f('wavefront_vs_megakernel')} | {f('gpu_vs_cpu_same_seed')} | "
                         f"{f('cpu_vs_cpu_other_seed')} | {c.get('nonfinite_samples', '-')} |")
        lines.append("")
    if d["builds"]:
        lines += ["## Kernel builds (the driver's compile, cold)", "", "| first render | program | features | seconds |",
                  "|---|---|---|--:|"]
        lines += [f"| {b['scene']} | {b['integrator']}, {b['schedule']} | {b['features']} | {b['seconds']:.2f} |"
                  for b in d["builds"]]
        lines.append("")
    if d["speed"]:
        lines += ["## Throughput (timed renders, 1024 wide unless the row says)", "",
                  "| scene | triangles | configuration | spp | M samples/s | M rays/s | intersect kernel M rays/s "
                  "| host share |", "|---|--:|---|--:|--:|--:|--:|--:|"]
        for s in d["speed"]:
            k = s["closest_mrays_per_s_kernel"]
            lines.append(f"| {s['scene']} | {s['triangles']} | {s['config']} | {s['spp']} | "
                         f"{s['msamples_per_s']:.1f} | {s['mrays_per_s']:.0f} | {'-' if k is None else f'{k:.0f}'} | "
                         f"{100 * s['host_share']:.1f}% |")
        lines.append("")
    if d["rays"]:
        lines += ["## Rays (wavefront_ray_bench --device gpu)", "",
                  "| scene | triangles | kernels | set | rays | ours M rays/s | Embree 1 M rays/s | Embree 8 "
                  "| ours/Embree | agreement |", "|---|--:|---|---|--:|--:|--:|--:|--:|--:|"]
        for r in d["rays"]:
            for s in r["sets"]:
                p = s.get("embree_packet8_mrays_per_s")
                lines.append(f"| {os.path.basename(r['scene'])} | {r['triangles']} | {r.get('kernels', 'auto')} | "
                             f"{s['set']} | {s['rays']} | "
                             f"{s['ours_mrays_per_s']:.0f} | {s['embree_mrays_per_s']:.0f} | "
                             f"{'-' if p is None else f'{p:.0f}'} | {s['ours_over_embree']:.2f} | "
                             f"{100 * s['agreement']:.3f}% |")
        lines.append("")
    if d.get("registers"):
        kernels = {}
        for r in d["registers"]:
            kernels.setdefault(r["kernel"], []).append(r)
        def span(rs, key):
            lo, hi = min(r.get(key, 0) for r in rs), max(r.get(key, 0) for r in rs)
            return str(lo) if lo == hi else f"{lo}–{hi}"
        lines += ["## Registers (NVIDIA's compiler, -cl-nv-verbose), over the programs above", "",
                  "| kernel | programs | registers | stack frame (bytes) | spill stores | shared memory |",
                  "|---|--:|--:|--:|--:|--:|"]
        lines += [f"| {k} | {len(rs)} | {span(rs, 'registers')} | {span(rs, 'stack')} | {span(rs, 'spill_stores')} | "
                  f"{span(rs, 'smem')} |" for k, rs in kernels.items()]
        lines.append("")
    if d["skipped"]:
        lines += ["## Not done", ""] + [f"- {s}" for s in d["skipped"]] + [""]
    return "\n".join(lines)


def make_references(args):
    """The CPU renders the checks compare against: seeds 1 and 2 of each check scene."""
    os.makedirs(args.make_references, exist_ok=True)
    wavefront = os.path.join(args.bin, "wavefront")
    for _, scene, extra in CHECK_SCENES:
        for seed in (1, 2):
            subprocess.run([wavefront, "render", scene_path(args.real, scene), "--device", "cpu"] + CHECK_FLAGS +
                           ["--seed", str(seed), "--quiet", "-o", reference_path(args.make_references, scene, seed)]
                           + extra, check=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--out", default=os.path.join(ROOT, "bench", "results"))
    p.add_argument("--bin", default=os.path.join(ROOT, "build"))
    p.add_argument("--real", default=os.path.join(ROOT, "..", "shared", "scenes-real"))
    p.add_argument("--budget", type=float, default=420, help="seconds for the whole run (default 420)")
    p.add_argument("--seconds", type=float, default=3, help="each timed render's length (default 3)")
    p.add_argument("--rays", type=int, default=4000000)
    p.add_argument("--device", default="gpu", help="the OpenCL device, as `wavefront render --device` (default gpu)")
    p.add_argument("--only", choices=["all", "knobs", "traversal"], default="all",
                   help="knobs: the Cornell box's local sizes, queue pushes, group schedule and one shade kernel "
                        "alone; traversal: "
                        "the ray bench with a GPU's kernels and a CPU's")
    p.add_argument("--references", help="CPU renders of the check scenes, from --make-references")
    p.add_argument("--make-references", metavar="DIR", help="render them on the CPU device into DIR, and stop")
    args = p.parse_args()
    if args.make_references:
        return make_references(args)
    os.makedirs(args.out, exist_ok=True)
    run = Run(args)
    try:
        done = run.call("devices", [run.program("wavefront"), "devices"], limit=60)
        kind = f"type {args.device}" if args.device in ("gpu", "cpu") else ""
        if args.device == "gpu" and (done is None or kind not in done.stdout) and register_unlisted_drivers(run):
            done = run.call("devices, the drivers found on disk named", [run.program("wavefront"), "devices"], limit=60)
        if done is None or kind not in done.stdout:
            run.save()
            sys.exit(f"gpu.py: `wavefront devices` lists no OpenCL {args.device} device (see gpu-run.log)")
        gpu = next(b for b in done.stdout.split("\n[") if kind in b)
        run.data["device"] = re.sub(r"^\[?\d+\]\s*", "", " ".join(l.strip() for l in gpu.splitlines()))
        run.save()
        name, scene, extra = CHECK_SCENES[0]
        check_step(run, name, scene, extra)
        if not run.data["checks"]:  # the simplest program failed: the rest would fail alike, slowly
            sys.exit("gpu.py: the Cornell box does not render on the device (see gpu-run.log)")
        for label, flags in INTEGRATORS:
            speed_row(run, label, name, scene, extra + flags)
        if args.only == "knobs":
            for label, flags in KNOBS:
                speed_row(run, label, name, scene, extra + flags)
            return
        if args.only == "traversal":  # a GPU's traversal against a CPU's, on the same device
            for scene in RAY_SCENES:
                for kernels in ("gpu", "cpu"):
                    ray_step(run, scene, kernels)
            return
        ray_step(run, RAY_SCENES[0])
        for name, scene, extra in SPEED_SCENES[3:]:
            for label, flags in INTEGRATORS:
                speed_row(run, label, name, scene, extra + flags)
        for scene in RAY_SCENES[1:]:
            ray_step(run, scene)
        for name, scene, extra in CHECK_SCENES[1:]:
            check_step(run, name, scene, extra)
        for name, scene, extra in SPEED_SCENES[1:3]:
            for label, flags in INTEGRATORS:
                speed_row(run, label, name, scene, extra + flags)
        name, scene, extra = CHECK_SCENES[0]
        for label, flags in SCHEDULES:
            speed_row(run, label, name, scene, extra + flags)
        for label, flags in INTEGRATORS:
            for pool in POOLS:
                speed_row(run, f"{label}, pool {pool}, 2048 wide", name, scene,
                          extra + flags + ["--pool-size", str(pool)], width=2048)
        for label, flags in KNOBS:
            speed_row(run, label, name, scene, extra + flags)
    finally:
        log = os.environ.get("WF_KERNEL_BUILD_LOG")
        if log and os.path.exists(log):
            run.data["registers"] = registers(log)
        run.save()
        shutil.rmtree(run.tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
