"""test_module.py -- `import wavefront` as a scheduling study uses it: the
image and bounce layers as NumPy arrays with the command line's pixels,
statistics whose counts agree with one another, every flag as a keyword,
denoise=True giving the denoised image and keeping the noisy one,
errors as exceptions with the command line's message, a progress callback,
and Ctrl-C that stops the render cleanly and raises KeyboardInterrupt.
Run by ctest (Python.Module) with build/python on PYTHONPATH."""

import inspect
import os
import pathlib
import signal
import subprocess
import sys
import tempfile

import numpy as np
import pytest

import wavefront

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORNELL = os.path.join(ROOT, "scenes", "cornell-box.gltf")
SMALL = dict(width=48, height=36, spp=4, seed=3)


@pytest.fixture(scope="module")
def cache():
    with tempfile.TemporaryDirectory() as folder:
        yield folder


def test_devices_are_listed():
    devices = wavefront.devices()
    assert devices and devices[0].index == 0
    assert devices[0].type in ("cpu", "gpu", "accelerator", "other")


def test_a_render_gives_the_command_lines_bytes(cache):
    result = wavefront.render(CORNELL, cache_dir=cache, **SMALL)
    assert result.image.shape == (36, 48, 3) and result.image.dtype == np.float32
    assert result.spp == 4 and np.isfinite(result.image).all() and result.image.mean() > 0.1
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "cli.exr")
        subprocess.run([os.environ.get("WF_BINARY", os.path.join(ROOT, "build", "wavefront")), "render", CORNELL,
                        "-o", out, "--cache-dir", cache, "--quiet"] + [f"--{k}={v}" for k, v in SMALL.items()],
                       check=True)
        # The module writes the same file when asked, through the same code.
        written = os.path.join(folder, "module.exr")
        wavefront.render(CORNELL, output=written, cache_dir=cache, **SMALL)
        assert np.array_equal(wavefront.read_image(out), result.image)
        assert np.array_equal(wavefront.read_image(written), result.image)


def test_schedules_pool_sizes_and_a_loaded_scene_give_the_same_bytes(cache):
    scene = wavefront.load_scene(CORNELL)
    assert scene.triangles == 32 and scene.materials == 4 and scene.has_camera
    reference = wavefront.render(scene, cache_dir=cache, **SMALL).image
    for flags in (dict(schedule="refill", pool_size=500), dict(schedule="fullest", local_size=32),
                  dict(integrator="megakernel")):
        assert np.array_equal(wavefront.render(CORNELL, cache_dir=cache, **SMALL, **flags).image, reference), flags


def test_statistics_agree_with_one_another(cache):
    result = wavefront.render(CORNELL, cache_dir=cache, schedule="refill", pool_size=1000, aov="bounces", **SMALL)
    st = result.stats
    pixels = 48 * 36
    assert st.samples == pixels * 4 and st.schedule == "refill" and st.pool_size == 1000
    reads = st.counter_reads
    assert reads.shape == (st.iterations, len(wavefront.Stats.counter_read_columns))
    assert reads[:, 5].sum() == st.closest_rays and reads[:, 6].sum() == st.shadow_rays
    assert reads[:, 7].sum() == st.samples == st.path_lengths.sum()
    assert set(st.stages) >= {"generate", "intersect", "shade", "accumulate"}
    assert st.stages["intersect"]["launches"] > 0 and st.kernel_seconds > 0.0
    assert 0.0 < st.pool_occupancy <= 1.0
    assert sorted(result.bounce_layers) == [f"bounce{i}" for i in range(7)] + ["bounce7plus"]
    # The layers add up to the image.
    total = sum(result.bounce_layers.values())
    assert np.allclose(total, result.image, rtol=1e-4, atol=1e-5)
    assert [c.spp for c in result.checkpoints] == [1, 2, 4]
    assert "samples " in result.report


def test_group_occupancy_counts_busy_slots_not_samples(cache):
    # One slot a pixel, and launches of 1, 1 and 2 samples a slot (the rounds
    # of 1, 2 and 4 spp): every slot busy in each, the pool full, however
    # many samples its slots start.
    st = wavefront.render(CORNELL, cache_dir=cache, schedule="group", pool_size=48 * 36, **SMALL).stats
    assert st.schedule == "group" and st.samples == 48 * 36 * 4 and st.iterations == 3
    assert st.pool_occupancy == 1.0


def test_first_hit_aovs_are_arrays(cache):
    result = wavefront.render(CORNELL, cache_dir=cache, aov=["albedo", "normal", "depth"], **SMALL)
    assert sorted(result.aovs) == ["albedo", "depth", "normal"]
    assert result.aovs["albedo"].shape == (36, 48, 3) and result.aovs["depth"].shape == (36, 48)
    depth = result.aovs["depth"]
    assert (result.aovs["albedo"] <= 1.0).all() and np.median(depth) > 0.0
    assert ((depth == 0.0) == (result.aovs["albedo"].sum(axis=2) == 0.0)).all()  # escaped: both 0
    lengths = np.linalg.norm(result.aovs["normal"], axis=2)
    assert (lengths <= 1.0 + 1e-5).all() and np.median(lengths) > 0.99
    assert np.array_equal(result.image, wavefront.render(CORNELL, cache_dir=cache, **SMALL).image)


def test_errors_carry_the_command_lines_message(cache):
    with pytest.raises(wavefront.InputError, match=r"^render: --spp: 0 is not in 1 to 16777216$"):
        wavefront.render(CORNELL, spp=0)
    with pytest.raises(ValueError, match="no-such.gltf"):
        wavefront.render(os.path.join(ROOT, "no-such.gltf"), spp=1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'frobnicate'"):
        wavefront.render(CORNELL, frobnicate=1)
    with pytest.raises(wavefront.InputError, match="--device 9: no such device"):
        wavefront.render(CORNELL, device=9, cache_dir=cache, **SMALL)


def test_progress_is_reported_and_its_errors_stop_the_render(cache):
    seen = []
    wavefront.render(CORNELL, progress=lambda s: seen.append(s.samples), cache_dir=cache, **SMALL)
    assert seen and seen == sorted(seen) and seen[-1] == 48 * 36 * 4

    def fail(_):
        raise ZeroDivisionError("from the callback")
    with pytest.raises(ZeroDivisionError, match="from the callback") as raised:
        wavefront.render(CORNELL, progress=fail, cache_dir=cache, **SMALL)
    partial = raised.value.result  # what the render had computed when it stopped
    assert partial.image.shape == (36, 48, 3) and 1 <= partial.spp < 4 and partial.image.mean() > 0.0


def test_images_are_written_and_shown_as_the_command_line_writes_them(cache):
    result = wavefront.render(CORNELL, cache_dir=cache, **SMALL)
    shown = wavefront.srgb(result.image, exposure=1.0)
    assert shown.shape == result.image.shape and shown.min() >= 0.0 and 0.9999 < shown.max() <= 1.0  # the lamp clips
    with tempfile.TemporaryDirectory() as folder:
        png, exr = os.path.join(folder, "a.png"), pathlib.Path(folder) / "a.exr"
        wavefront.write_image(png, result.image, exposure=1.0)
        wavefront.write_image(exr, result.image)
        assert np.array_equal(wavefront.read_image(exr), result.image)
        decoded = wavefront.read_image(png)  # 8 bits of the sRGB curve: within half a step of the display image
        assert np.abs(wavefront.srgb(decoded) - shown).max() <= 0.5 / 255 + 1e-6
        with pytest.raises(wavefront.InputError, match="no/such/folder"):
            wavefront.write_image(os.path.join(folder, "no/such/folder/x.png"), result.image)


def test_the_study_sees_every_stage_in_the_default_schedule(cache):
    given = []
    result = wavefront.render(CORNELL, cache_dir=cache, progress=lambda s: given.append(s.counter_reads),
                              **SMALL)
    stats, columns = result.stats, wavefront.Stats.counter_read_columns
    assert stats.schedule == "group"  # the CPU's default: one launch a round, its queues local
    total = stats.counter_reads.sum(axis=0)
    entered = dict(zip(columns, total))
    assert entered["regenerate"] == entered["finished"] == stats.samples == 48 * 36 * 4
    assert entered["extend"] == stats.closest_rays and entered["shadow"] == stats.shadow_rays > 0
    assert 0 < entered["continue"] <= entered["extend"]
    # The callback sees each read once: the reads since its previous call.
    assert sum(len(reads) for reads in given) == len(stats.counter_reads) and len(given[-1]) >= 1


def test_paths_may_be_path_objects(cache):
    path = pathlib.Path(CORNELL)
    assert wavefront.load_scene(path).triangles == 32
    with tempfile.TemporaryDirectory() as folder:
        out = pathlib.Path(folder) / "out.exr"
        result = wavefront.render(path, output=out, cache_dir=pathlib.Path(cache), **SMALL)
        assert np.array_equal(wavefront.read_image(out), result.image)


def test_a_loaded_scene_renders_through_the_camera_it_was_loaded_with(cache):
    scene = wavefront.load_scene(CORNELL, camera=0)
    assert np.array_equal(wavefront.render(scene, cache_dir=cache, **SMALL).image,
                          wavefront.render(CORNELL, camera=0, cache_dir=cache, **SMALL).image)
    with pytest.raises(wavefront.InputError, match="camera 1 is not the one .* was loaded with \\(0\\)"):
        wavefront.render(scene, camera=1, cache_dir=cache, **SMALL)


def test_a_loaded_scene_renders_with_the_instancing_it_was_loaded_with(cache):
    scene = wavefront.load_scene(CORNELL, instancing="all")
    assert scene.placed_triangles == scene.triangles == 32  # no mesh of the box is placed twice
    with pytest.raises(wavefront.InputError, match="instancing off is not the one .* was loaded with \\(all\\)"):
        wavefront.render(scene, instancing="off", cache_dir=cache, **SMALL)
    with pytest.raises(wavefront.InputError, match="instancing 'some'"):
        wavefront.load_scene(CORNELL, instancing="some")


def test_a_camera_set_by_eye_target_and_field_of_view(cache):
    # The Cornell box's own camera, given as eye, target and field of view: the file camera's pixels.
    file_camera = wavefront.render(CORNELL, cache_dir=cache, **SMALL).image
    same = wavefront.render(CORNELL, look_at=(278, 273, -800, 278, 273, 0), fov=39.3, cache_dir=cache, **SMALL)
    assert np.array_equal(same.image, file_camera)
    closer = wavefront.render(CORNELL, look_at=[278, 273, -500, 278, 273, 0, 0, 1, 0], cache_dir=cache, **SMALL)
    assert not np.array_equal(closer.image, file_camera)
    with pytest.raises(TypeError, match="look_at"):
        wavefront.render(CORNELL, look_at=5, cache_dir=cache, **SMALL)
    with pytest.raises(TypeError, match="look_at"):
        wavefront.render(CORNELL, look_at=("a", 1, 2, 3, 4, 5), cache_dir=cache, **SMALL)
    with pytest.raises(wavefront.InputError, match="--look-at 1.0,2.0,3.0: expected six or nine numbers"):
        wavefront.render(CORNELL, look_at=(1, 2, 3), cache_dir=cache, **SMALL)
    with pytest.raises(wavefront.InputError, match="the eye is the target"):
        wavefront.render(CORNELL, look_at=(1, 2, 3, 1, 2, 3), cache_dir=cache, **SMALL)


def test_version_and_what_objects_print(cache):
    binary = os.environ.get("WF_BINARY", os.path.join(ROOT, "build", "wavefront"))
    cli = subprocess.run([binary, "--version"], check=True, capture_output=True, text=True).stdout
    assert cli.splitlines()[0] == "wavefront " + wavefront.__version__
    result = wavefront.render(CORNELL, cache_dir=cache, **SMALL)
    assert repr(result).startswith("<wavefront.Result 48 x 36, 4 spp on ")
    assert repr(result.stats).startswith("<wavefront.Stats wavefront, group: 6912 samples in ")
    assert repr(result.checkpoints[-1]).startswith("<wavefront.Checkpoint 4 spp at ")
    assert " -> " not in result.report  # no file was written
    assert result.stats.schedule == "group"
    megakernel = wavefront.render(CORNELL, integrator="megakernel", cache_dir=cache, **SMALL)
    assert megakernel.stats.schedule is None and megakernel.stats.integrator == "megakernel"
    assert repr(megakernel.stats).startswith("<wavefront.Stats megakernel: ")


def test_every_flag_is_a_typed_keyword_with_its_default_and_help(cache):
    binary = os.environ.get("WF_BINARY", os.path.join(ROOT, "build", "wavefront"))
    help_text = subprocess.run([binary, "render", "--help"], check=True, capture_output=True, text=True).stdout
    flags = {line.split()[0].split(",")[-1][2:].replace("-", "_") for line in help_text.splitlines()
             if line.startswith("  -")} - {"help"}
    parameters = inspect.signature(wavefront.render).parameters
    assert flags == set(parameters) - {"scene", "progress"}
    assert all(parameters[f].kind == inspect.Parameter.KEYWORD_ONLY for f in flags)
    assert parameters["spp"].default == 16 and parameters["spp"].annotation is int
    assert parameters["schedule"].default == "auto" and parameters["quiet"].default is False
    assert parameters["roulette_cap"].annotation is float and parameters["device"].default is None
    assert "    spp: Samples per pixel (default: 16)" in wavefront.render.__doc__

    for keywords, message in ((dict(sppp=4), "unexpected keyword argument 'sppp'"),
                              (dict(spp=True), "spp takes an int, not bool"),
                              (dict(spp="4"), "spp takes an int, not str"),
                              (dict(quiet=0), "quiet takes True or False, not int"),
                              (dict(aov=[1]), "aov takes a str or a list of str, not int"),
                              (dict(output=3), "output takes a str or os.PathLike, not int"),
                              (dict(reference=np.zeros((4, 4))), "reference takes a path or a height x width")):
        with pytest.raises(TypeError, match=message):
            wavefront.render(CORNELL, cache_dir=cache, **{**SMALL, **keywords})
    with pytest.raises(wavefront.InputError, match=r"^render: --width: -5 is not in 1 to 32768$"):
        wavefront.render(CORNELL, width=-5)


def test_arrays_and_devices_are_accepted_as_such(cache):
    result = wavefront.render(CORNELL, cache_dir=cache, device=wavefront.devices()[0], max_depth="unlimited",
                              **SMALL)
    again = wavefront.render(CORNELL, cache_dir=cache, reference=result.image, spp=4, width=48, height=36, seed=3)
    assert again.checkpoints[-1].relmse == 0.0  # the array is handed to the render as it is
    with pytest.raises(wavefront.InputError, match="the reference is 10x10 but the render is 48x36"):
        wavefront.render(CORNELL, cache_dir=cache, reference=np.zeros((10, 10, 3)), **SMALL)


# Ctrl-C while a long render runs in another Python: the render stops at
# once, cleanly, and KeyboardInterrupt reaches the script, which goes on.
SCRIPT = """
import sys, wavefront
started = []
def progress(stats):
    if not started:
        started.append(1)
        print("rendering", flush=True)
try:
    wavefront.render(sys.argv[1], spp=1 << 20, width=64, cache_dir=sys.argv[2], progress=progress)
except KeyboardInterrupt as stop:
    print("interrupted", stop.result.image.shape, stop.result.spp > 0, flush=True)
"""


def test_ctrl_c_stops_the_render_and_raises_keyboard_interrupt(cache):
    child = subprocess.Popen([sys.executable, "-c", SCRIPT, CORNELL, cache], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "rendering"  # a sign of life, then the signal
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=300)
    assert child.returncode == 0 and out.strip() == "interrupted (64, 64, 3) True"  # with what it had computed


def denoised_or_skip(cache, **keywords):
    """render(denoise=True), skipped where Open Image Denoise is absent (not in CI: WF_REQUIRE_OIDN=1)."""
    try:
        return wavefront.render(CORNELL, cache_dir=cache, denoise=True, **SMALL, **keywords)
    except wavefront.InputError as e:
        if "Open Image Denoise not found" not in str(e) or os.environ.get("WF_REQUIRE_OIDN") == "1":
            raise
        pytest.skip(f"denoising not tested: {e}")


def test_denoise_gives_the_denoised_image_and_keeps_the_noisy_one(cache):
    # Independent samples: noise enough that the filter's smoothing shows beside the image's edges.
    result = denoised_or_skip(cache, sampler="independent")
    plain = wavefront.render(CORNELL, cache_dir=cache, sampler="independent", **SMALL)
    assert plain.noisy is None
    assert np.array_equal(result.noisy, plain.image)  # the same samples, before the filter
    assert result.image.shape == plain.image.shape and result.image.dtype == np.float32
    assert np.isfinite(result.image).all() and not np.array_equal(result.image, plain.image)
    # Smoother: neighbouring pixels differ less (0.52 times as much at this seed; edges stay). The
    # error against a reference is bounded in tests/render/test_denoise.cpp.
    assert np.abs(np.diff(result.image, axis=1)).mean() < 0.7 * np.abs(np.diff(plain.image, axis=1)).mean()
    assert sorted(result.aovs) == ["albedo", "normal"]  # the guides it turned on
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "denoised.exr")
        denoised_or_skip(cache, output=out, sampler="independent")
        assert np.array_equal(wavefront.read_image(out), result.image)


def test_denoise_without_the_library_says_how_to_install_it(cache):
    # A process of its own: a library once opened stays open.
    code = ("import wavefront, sys\n"
            "try:\n"
            f"    wavefront.render({CORNELL!r}, denoise=True, cache_dir={cache!r}, width=8, spp=1)\n"
            "except wavefront.InputError as e:\n"
            "    print(e); sys.exit(0)\n"
            "sys.exit(1)\n")
    env = dict(os.environ, WF_OIDN_LIBRARY="/nonexistent/libOpenImageDenoise.so.2")
    run = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "Open Image Denoise not found" in run.stdout and "pip install pyoidn" in run.stdout
