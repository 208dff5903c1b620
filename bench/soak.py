#!/usr/bin/env python3
"""soak.py -- renders many times in one process and checks that nothing
grows (issue 32, "Soak"). This file owns the soak's facts: the list of
configurations a cycle renders, what is measured after each cycle, and the
criterion that says whether something grew. tests/python/test_soak.py
imports it for a short soak under ctest; run as a script it is the long
soak: the module, then the command line with `--device all`, and a Markdown
table of the figures.

A cycle renders every configuration of CONFIGS once through
`wavefront.render`, small (32x24, 2 spp): both Cornell boxes, a loaded Scene
reused, every schedule (group, refill, passes, fullest) and the megakernel,
pool sizes, the AOV and bounce layers, and a render that its progress callback
stops by raising. (A variant that needs a program of its own costs 3-7 s of
compiling in the first cycle: the list is kept short enough for the ctest
version to stay under 60 s on a fresh machine.)
Each configuration's arrays must have the bytes of its first render; the
stopped one must stop at its first report. After each cycle the process's
resident memory, file descriptors, threads and memory maps are read from
/proc/self, and the heap in use from glibc's malloc_info. OpenCL objects are
seen only through these: the C++ wrappers keep no count of them, and PoCL's
CPU device keeps a buffer in malloc'd host memory (heap, RSS), a compiled
kernel as a loaded library (maps) and its work in threads of its own.

Usage: python3 bench/soak.py [--renders N] [--cli-runs N] [--output FILE]
       (after scripts/setup.sh; the defaults, 1000 renders and 1000 runs,
       take about 6 minutes on 2 cores, 5 of them the command line's runs)
"""

import argparse
import ctypes
import datetime
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

import wavefront

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BOX = os.path.join(ROOT, "scenes", "cornell-box.gltf")
GLASS = os.path.join(ROOT, "scenes", "cornell-glass.gltf")
SMALL = dict(width=32, height=24, spp=2, seed=7)
LOADED = "loaded"  # stands for the one Scene object that every cycle reuses
STOPPED = "stopped"

# name, scene (a path or LOADED), flags over SMALL. The stopped render asks
# for many samples, so that stopping is seen: it ends after its first report.
CONFIGS = [
    ("box", BOX, {}),
    ("glass", GLASS, {}),
    ("loaded scene", LOADED, {}),
    ("refill, pool 256", BOX, dict(schedule="refill", pool_size=256)),
    ("group, pool 512", GLASS, dict(schedule="group", pool_size=512)),
    ("passes, pool 640", BOX, dict(schedule="passes", pool_size=640)),
    ("fullest, pool 500", BOX, dict(schedule="fullest", pool_size=500)),
    ("megakernel", GLASS, dict(integrator="megakernel")),
    ("every AOV and layer, refill", GLASS, dict(aov=["albedo", "normal", "depth", "bounces"], schedule="refill",
                                                 pool_size=384)),
    (STOPPED, BOX, dict(spp=1024)),
]

# The criterion. The first cycles compile kernels, fill PoCL's and the
# allocator's caches and start PoCL's threads: WARMUP cycles are not judged.
# Memory is judged by its floor, the least of TAIL cycles, first and last:
# what a cycle holds above it is transient (blocks that PoCL's threads keep
# in their tcache, a peak glibc has not yet trimmed: up to 8 MiB of heap, in
# about one cycle in five), and a leak raises the floor. The heap in use
# (malloc_info) is the sharp measure: RSS does not move while a leak fills
# blocks that were freed but stay resident (the kernel compiler leaves
# plenty). Measured here: a sound soak's heap floor drifts by under 100
# bytes a render (0.04-0.10 MiB over 1000 in three long soaks,
# bench/results/soak.md), its RSS moves up and down by up to 1.4 MiB (pages
# trimmed and touched again); keeping each Result alive (image, variance,
# AOV and bounce layers: about 35 KiB a render) raised the heap's floor
# 3.3 MiB in 15 cycles and RSS by under 1 MiB in 24. Hence
# HEAP_TOLERANCE_MIB, 1 MiB: ten times the drift of 100 cycles, passed by
# that leak within 4 cycles; and RSS_TOLERANCE_MIB, 4 MiB, about three times
# RSS's noise, for what the heap does not see (pages that PoCL or Python map
# themselves). A leak too slow for these still rises at
# nearly every cycle: memory that rises at more than RISING_SHARE of the
# judged cycles, by more than RISING_MIB in all, is growth too (one 32x24
# image copy kept a render, 81 KiB a cycle: the heap rose at 14 of 14
# cycles, 1.12 MiB). File descriptors and threads must be exactly what they
# were after the warm-up. Memory maps may grow by MAPS_SLACK lines (glibc
# and Python map and unmap large blocks and arenas as they go; a leaked
# program would add maps at every render).
WARMUP = 3
CLI_WARMUP = 2  # this process's first two reads of an EXR start OpenImageIO's threads and map what it loads
TAIL = 3
HEAP_TOLERANCE_MIB = 1.0
RSS_TOLERANCE_MIB = 4.0
RISING_SHARE = 0.8
RISING_MIB = 0.5
MAPS_SLACK = 4


_libc = ctypes.CDLL(None)
_libc.open_memstream.restype = ctypes.c_void_p
_libc.open_memstream.argtypes = [ctypes.POINTER(ctypes.c_char_p), ctypes.POINTER(ctypes.c_size_t)]
_libc.malloc_info.argtypes = [ctypes.c_int, ctypes.c_void_p]
_libc.fclose.argtypes = [ctypes.c_void_p]
_libc.free.argtypes = [ctypes.c_void_p]


def heap_in_use():
    """Bytes that glibc's malloc has handed out and not had back, over every
    arena (PoCL's threads allocate in arenas of their own) and its mmap'd
    blocks: from malloc_info(3), written to memory, not to a descriptor."""
    text, size = ctypes.c_char_p(), ctypes.c_size_t()
    stream = _libc.open_memstream(ctypes.byref(text), ctypes.byref(size))
    _libc.malloc_info(0, stream)
    _libc.fclose(stream)
    xml = ctypes.string_at(text, size.value).decode()
    _libc.free(text)
    totals = xml[xml.rfind("</heap>"):]  # the totals over all arenas follow the last one

    def total(pattern):
        return int(re.search(pattern, totals).group(1))
    free = total(r'<total type="fast" count="\d+" size="(\d+)"') + total(r'<total type="rest" count="\d+" size="(\d+)"')
    return total(r'<system type="current" size="(\d+)"') - free + total(r'<total type="mmap" count="\d+" size="(\d+)"')


def resources():
    """What this process holds now: RSS and the heap in use in KiB, open file
    descriptors, threads and memory maps."""
    heap = heap_in_use()
    with open("/proc/self/statm") as f:
        rss_pages = int(f.read().split()[1])
    with open("/proc/self/maps") as f:
        maps = sum(1 for _ in f)
    return dict(rss_kib=rss_pages * os.sysconf("SC_PAGE_SIZE") // 1024, heap_kib=heap // 1024,
                fds=len(os.listdir("/proc/self/fd")), threads=len(os.listdir("/proc/self/task")), maps=maps)


class Stop(Exception):
    """Raised by the progress callback of the stopped render."""


def arrays(result):
    """Every array a render returns, by name: what must keep its bytes."""
    named = {"image": result.image, "variance": result.variance}
    named.update({f"aov {k}": v for k, v in result.aovs.items()})
    named.update({f"layer {k}": v for k, v in result.bounce_layers.items()})
    return named


def render_stopped(scene, cache_dir, flags):
    """A render that its progress callback stops at the first report; returns
    the samples reported then, having checked that it stopped."""
    reports = []

    def progress(stats):
        reports.append(stats.samples)
        raise Stop()
    try:
        wavefront.render(scene, progress=progress, cache_dir=cache_dir, **flags)
    except Stop:
        pass
    else:
        raise AssertionError("the stopped render ran to its end: its progress callback never raised")
    full = flags["width"] * flags["height"] * flags["spp"]
    if len(reports) != 1 or not reports[0] < full:
        raise AssertionError(f"the stopped render reported {reports} of {full} samples: it did not stop at once")
    return reports[0]


class ModuleSoak:
    """Renders CONFIGS again and again in this process. cycle() renders each
    once, raises AssertionError where an array's bytes differ from the first
    render's, and returns resources() after it."""

    def __init__(self, cache_dir, configs=CONFIGS, small=SMALL):
        self.cache_dir = cache_dir
        self.configs = configs
        self.small = small
        self.scene = wavefront.load_scene(BOX)
        self.first = {}  # name -> arrays() of its first render
        self.renders = 0

    def cycle(self):
        for name, scene, flags in self.configs:
            scene = self.scene if scene is LOADED else scene
            flags = {**self.small, **flags}
            self.renders += 1
            if name == STOPPED:
                render_stopped(scene, self.cache_dir, flags)
                continue
            result = wavefront.render(scene, cache_dir=self.cache_dir, **flags)
            now = arrays(result)
            if name not in self.first:
                self.first[name] = {k: v.copy() for k, v in now.items()}
            first = self.first[name]
            if sorted(now) != sorted(first):
                raise AssertionError(f"{name}: render {self.renders} returned {sorted(now)}, the first {sorted(first)}")
            for key, array in now.items():
                if not np.array_equal(array, first[key]):
                    raise AssertionError(f"{name}: render {self.renders}: {key} differs from its first render")
        return resources()


FIELDS = ("rss_kib", "heap_kib", "fds", "threads", "maps")  # what resources() returns


def record(count, extra=()):
    """Room for `count` rows of resources() and of the `extra` (name, dtype)
    fields, allocated before a soak: a list that grew by a dict a run would
    itself grow RSS (by about 0.4 KiB a run, measured) and, at each new
    arena of Python's allocator, the maps."""
    return np.zeros(count, dtype=list(extra) + [(name, "i8") for name in FIELDS])


def runs_of(values):
    """[6, 6, 7, 7, 7] as '6 x2, 7 x3': a long list of counts, short."""
    out = []
    for v in values:
        if out and out[-1][0] == v:
            out[-1][1] += 1
        else:
            out.append([v, 1])
    return ", ".join(f"{v} x{n}" for v, n in out)


def growth(samples, warmup=WARMUP):
    """The criterion over resources() after each cycle (a list of dicts or a
    record()): a list of what grew, empty when nothing did."""
    judged = samples[warmup:]
    if len(judged) < 2 * TAIL:
        raise ValueError(f"{len(samples)} cycles: at least {warmup + 2 * TAIL} are needed to judge growth")
    problems = []
    base = samples[warmup - 1] if warmup else judged[0]
    for key in ("fds", "threads"):
        counts = [int(s[key]) for s in judged]
        if any(c != base[key] for c in counts):
            problems.append(f"{key}: {base[key]} after the warm-up, then {runs_of(counts)}")
    for key, label, tolerance in (("heap_kib", "heap", HEAP_TOLERANCE_MIB), ("rss_kib", "RSS", RSS_TOLERANCE_MIB)):
        mib = [float(s[key]) / 1024.0 for s in judged]
        start, end = min(mib[:TAIL]), min(mib[-TAIL:])
        if end - start > tolerance:
            problems.append(f"{label}: its floor grew {end - start:.2f} MiB over {len(judged)} cycles "
                            f"(from {start:.2f} to {end:.2f} MiB; at most {tolerance} MiB)")
        rises = sum(1 for a, b in zip(mib, mib[1:]) if b > a)
        if rises > RISING_SHARE * (len(mib) - 1) and mib[-1] - mib[0] > RISING_MIB:
            problems.append(f"{label}: rose at {rises} of {len(mib) - 1} cycles, {mib[-1] - mib[0]:.2f} MiB in all")
    maps = [int(s["maps"]) for s in judged]
    if max(maps) > base["maps"] + MAPS_SLACK:
        problems.append(f"memory maps: {base['maps']} after the warm-up, then {runs_of(maps)}")
    return problems


def cli_soak(rows, cache_dir, folder, report=None):
    """Runs `wavefront render --device all` on the box once for each row of
    `rows` (a record() with the fields seconds and child_rss_kib): each run
    must exit 0 and give the first run's pixels (the files differ in their
    date). It runs a copy of the binary taken before the first run, so that
    a rebuild during the soak neither breaks a run nor changes the program.
    Fills in each run's seconds, its peak RSS (through GNU time where
    /usr/bin/time is installed, else 0: a child's own ru_maxrss would count
    the pages of this process it was forked from) and this process's
    resources() after it. Returns the image."""
    binary = os.path.join(folder, "wavefront")
    shutil.copy2(os.environ.get("WF_BINARY", os.path.join(ROOT, "build", "wavefront")), binary)
    out, peak = os.path.join(folder, "cli.exr"), os.path.join(folder, "peak")
    timed = ["/usr/bin/time", "-f", "%M", "-o", peak] if os.path.exists("/usr/bin/time") else []
    command = timed + [binary, "render", BOX, "--device", "all", "-o", out, "--cache-dir", cache_dir, "--quiet"]
    command += [f"--{k}={v}" for k, v in SMALL.items()]
    first = None
    for run in range(len(rows)):
        start = time.monotonic()
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        rows["seconds"][run] = time.monotonic() - start
        if done.returncode != 0:
            raise AssertionError(f"CLI run {run + 1}: exit {done.returncode}: {done.stderr.decode(errors='replace')}")
        image = wavefront.read_image(out)
        os.remove(out)
        if first is None:
            first = image
        elif not np.array_equal(image, first):
            raise AssertionError(f"CLI run {run + 1}: the image differs from the first run's")
        if timed:
            with open(peak) as f:
                rows["child_rss_kib"][run] = int(f.read().split()[-1])
        for key, value in resources().items():
            rows[key][run] = value
        if report:
            report(run, rows[run])
    return first


def floors(samples, warmup=WARMUP, unit="cycles"):
    """One sentence: the floors that growth() compares, and the range."""
    judged = samples[warmup:]
    parts = []
    for key, label in (("heap_kib", "heap"), ("rss_kib", "RSS")):
        mib = [float(s[key]) / 1024.0 for s in judged]
        parts.append(f"{label} {min(mib[:TAIL]):.2f} MiB at its floor over the first {TAIL} judged {unit}, "
                     f"{min(mib[-TAIL:]):.2f} over the last {TAIL} (range {min(mib):.2f}-{max(mib):.2f})")
    return f"after the warm-up ({warmup} {unit[:-1] if warmup == 1 else unit}): " + "; ".join(parts) + "."


def table(rows, label, every):
    """A Markdown table of every `every`-th row and the last."""
    keys = [k for k in ("renders", "seconds", "child_rss_kib", "rss_kib", "heap_kib", "fds", "threads", "maps")
            if k in rows.dtype.names]
    heads = dict(renders="renders", seconds="s (run)", child_rss_kib="its peak RSS MiB", rss_kib="RSS MiB",
                 heap_kib="heap MiB", fds="fds", threads="threads", maps="maps")
    out = [f"| {label} | " + " | ".join(heads[k] for k in keys) + " |", "|--:|" + "--:|" * len(keys)]
    for i, row in enumerate(rows):
        if i % every and i != len(rows) - 1:
            continue
        cells = [f"{row[k] / 1024:.2f}" if k.endswith("kib") else f"{row[k]:.2f}" if k == "seconds" else str(row[k])
                 for k in keys]
        out.append(f"| {i + 1} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--renders", type=int, default=1000, help="renders through the module (whole cycles)")
    parser.add_argument("--cli-runs", type=int, default=1000, help="runs of the command line with --device all")
    parser.add_argument("--rows", type=int, default=20, help="about this many rows in each table")
    parser.add_argument("--output", help="also write the Markdown here (bench/results/soak.md)")
    args = parser.parse_args()
    cycles = max(WARMUP + 2 * TAIL, -(-args.renders // len(CONFIGS)))
    lines = []

    def say(text=""):
        print(text, flush=True)
        lines.append(text)

    device = wavefront.devices()[0]
    say("# Soak: many renders in one process, and the command line with `--device all`\n")
    count = len(wavefront.devices())
    say(f"{datetime.date.today().isoformat()}, {platform.node() or 'this machine'}: {os.cpu_count()} cores, "
        f"{count} OpenCL device{'s' if count > 1 else ''}, the first {device.name} ({device.platform}, "
        f"{device.version}){'' if count > 1 else '; `--device all` is that one device'}.\n")
    say("`python3 bench/soak.py " + " ".join(sys.argv[1:]) + "`, load average %.2f at the start (other work shares "
        "these cores; nothing here is a timing).\n" % os.getloadavg()[0])
    with tempfile.TemporaryDirectory() as folder:
        cache = os.path.join(folder, "cache")
        soak = ModuleSoak(cache)
        samples, start = record(cycles, [("renders", "i8")]), time.monotonic()
        for c in range(cycles):
            for key, value in soak.cycle().items():
                samples[key][c] = value
            samples["renders"][c] = soak.renders
            print(f"cycle {c + 1}/{cycles}: {samples[c]}", file=sys.stderr, flush=True)
        module_seconds = time.monotonic() - start
        problems = growth(samples)
        say("The criterion (what may not grow, and how far each figure may move): the comment above WARMUP in bench/soak.py.\n")
        say(f"## The module: {soak.renders} renders, {cycles} cycles of {len(CONFIGS)} configurations, "
            f"{module_seconds:.0f} s\n")
        say("Each configuration's image (and its AOV and bounce layers) had the bytes of its first render; "
            "the stopped render stopped at its first report every time. Resources after each cycle "
            "(OpenCL objects are seen through the heap, RSS, threads and maps: the wrappers keep no count):\n")
        say(table(samples, "cycle", max(1, cycles // args.rows)))
        verdict = "nothing grew." if not problems else "; ".join(problems)
        say("\nA" + floors(samples)[1:] + " Verdict: " + verdict + "\n")
        start = time.monotonic()
        rows = record(args.cli_runs, [("seconds", "f8"), ("child_rss_kib", "i8")])
        image = cli_soak(rows, cache, folder,
                         report=lambda r, row: print(f"CLI run {r + 1}: {row}", file=sys.stderr, flush=True))
        same = np.array_equal(image, soak.first["box"]["image"])
        say(f"## The command line: {args.cli_runs} runs of `wavefront render scenes/cornell-box.gltf --device all`, "
            f"{time.monotonic() - start:.0f} s\n")
        say("Every run exited 0 with the first run's pixels (compared as arrays: the EXR files differ in their "
            "header's date); those pixels " + ("are" if same else "are NOT") + " the module's bytes for the same "
            "flags. The peak RSS of each run, and this process's resources after it:\n")
        say(table(rows, "run", max(1, args.cli_runs // args.rows)))
        parent = growth(rows, warmup=CLI_WARMUP)
        peaks = [float(kib) / 1024.0 for kib in rows["child_rss_kib"][1:] if kib]
        if peaks and min(peaks[-TAIL:]) - min(peaks[:TAIL]) > RSS_TOLERANCE_MIB:
            parent.append(f"the runs' peak RSS: its floor grew from {min(peaks[:TAIL]):.2f} "
                          f"to {min(peaks[-TAIL:]):.2f} MiB")
        verdict = "nothing grew." if not parent else "; ".join(parent)
        say((f"\nThe runs' peak RSS: {min(peaks):.2f}-{max(peaks):.2f} MiB after the first. " if peaks else "\n")
            + "This process (its first runs read EXRs, which start OpenImageIO's threads and maps what it loads): "
            + floors(rows, warmup=CLI_WARMUP, unit="runs") + " Verdict: " + verdict)
        problems += parent + ([] if same else ["the CLI's image differs from the module's"])
    if args.output:
        with open(args.output, "w") as f:
            f.write("\n".join(lines) + "\n")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
