"""test_soak.py -- the short soak (issue 32): bench/soak.py's cycle of
renders, run CYCLES times in this process, must keep each configuration's
bytes and must not grow the heap, RSS, file descriptors, threads or memory
maps (OpenCL objects are seen only through these; see bench/soak.py). About
15 s on 2 cores; 40 s when PoCL's cache is empty and the first cycle compiles. The
long soak and its figures: `python3 bench/soak.py`, bench/results/soak.md.
Run by ctest (Python.Module) with build/python on PYTHONPATH."""

import importlib.util
import os
import tempfile

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
_spec = importlib.util.spec_from_file_location("soak", os.path.join(ROOT, "bench", "soak.py"))
soak = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(soak)

# The warm-up, then 15 judged cycles (150 renders): one leaked 32x24 image a
# render reaches the heap's tolerance within them (see soak.py's criterion).
CYCLES = soak.WARMUP + 15


def test_many_renders_in_one_process_keep_their_bytes_and_grow_nothing():
    with tempfile.TemporaryDirectory() as cache:
        run = soak.ModuleSoak(cache)
        samples = [run.cycle() for _ in range(CYCLES)]
    problems = soak.growth(samples)
    assert not problems, "; ".join(problems) + f"\nafter each cycle: {samples}"


def test_a_render_whose_bytes_change_is_caught():
    with tempfile.TemporaryDirectory() as cache:
        run = soak.ModuleSoak(cache, configs=soak.CONFIGS[:1])
        run.cycle()
        run.small = dict(soak.SMALL, seed=soak.SMALL["seed"] + 1)
        with pytest.raises(AssertionError, match="box: render 2: image differs from its first render"):
            run.cycle()


def flat(cycles=soak.WARMUP + 15):
    return [dict(rss_kib=250_000, heap_kib=74_000, fds=6, threads=8, maps=2026) for _ in range(cycles)]


def test_the_criterion_sees_each_kind_of_growth():
    samples = flat()
    # What a sound soak shows: a transient peak, a few KiB of drift.
    samples[7]["heap_kib"] += 8_000
    samples[9]["rss_kib"] += 2_000
    for i, s in enumerate(samples):
        s["heap_kib"] += 2 * i
    assert soak.growth(samples) == []

    def grown(change):
        samples = flat()
        for i, s in enumerate(samples):
            change(i, s)
        return " ".join(soak.growth(samples))
    assert "heap: its floor grew" in grown(lambda i, s: s.update(heap_kib=s["heap_kib"] + 90 * i))
    assert "RSS: its floor grew" in grown(lambda i, s: s.update(rss_kib=s["rss_kib"] + 400 * i))
    assert "RSS: rose at" in grown(lambda i, s: s.update(rss_kib=s["rss_kib"] + 40 * i))
    assert "fds" in grown(lambda i, s: s.update(fds=7) if i == 12 else None)
    assert "threads" in grown(lambda i, s: s.update(threads=9) if i > 10 else None)
    assert "memory maps" in grown(lambda i, s: s.update(maps=s["maps"] + i // 2))
    with pytest.raises(ValueError):
        soak.growth(flat(soak.WARMUP + 2))
