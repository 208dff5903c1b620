"""test_command_line.py -- `python -m wavefront` is the `wavefront` program:
a render writes the image with the program's pixels and closing report, and a
bad flag exits 2 with the program's one-line error. Run by ctest
(Python.Module, and Python.PipInstallBuildsTheModule against the installed
copy), with WF_BINARY naming the program to compare with."""

import os
import subprocess
import sys
import tempfile

import pytest

import wavefront

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORNELL = os.path.join(ROOT, "scenes", "cornell-box.gltf")
BINARY = os.environ.get("WF_BINARY", os.path.join(ROOT, "build", "wavefront"))


@pytest.fixture(scope="module")
def cache():
    with tempfile.TemporaryDirectory() as folder:
        yield folder


def python_m(*args):
    return subprocess.run([sys.executable, "-m", "wavefront", *args], capture_output=True, text=True)


def test_python_m_wavefront_renders_as_the_program_does(cache, tmp_path):
    flags = ["--spp", "1", "--width", "32", "--cache-dir", cache]
    out = tmp_path / "X.png"
    run = python_m("render", CORNELL, *flags, "-o", str(out))
    assert run.returncode == 0, run.stderr
    assert f"image      32 x 32, 1 spp -> {out}" in run.stdout
    program = tmp_path / "program.png"
    subprocess.run([BINARY, "render", CORNELL, *flags, "-o", str(program), "--quiet"], check=True)
    image = wavefront.read_image(out)
    assert image.shape == (32, 32, 3) and (wavefront.read_image(program) == image).all()


def test_a_bad_flag_exits_2_with_the_programs_one_line_error():
    run = python_m("render", CORNELL, "--no-such-flag")
    program = subprocess.run([BINARY, "render", CORNELL, "--no-such-flag"], capture_output=True, text=True)
    assert run.returncode == program.returncode == 2
    assert run.stdout == "" and run.stderr == program.stderr
    assert run.stderr.startswith("error: render: ") and run.stderr.count("\n") == 1
