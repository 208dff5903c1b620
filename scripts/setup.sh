#!/usr/bin/env bash
# scripts/setup.sh [--tests] — installs the Debian packages the project needs
# (when missing) and builds the renderer, build/wavefront, and the Python
# module (`import wavefront`) first of all, so that a first picture needs no
# more. --tests then builds the test suite too
# (build/wavefront_tests and the tools its tests run). Safe to run again: it
# only installs and rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

case "${1:-}" in
  "") tests=0 ;;
  --tests) tests=1 ;;
  *) echo "scripts/setup.sh: unknown argument '$1' (expected nothing or --tests)" >&2; exit 2 ;;
esac

# The tests also compile the kernels for AMD GPUs (bench/gpu_isa.py --check)
# and format the man page for 80 columns (nroff, groff-base).
extra=()
if ((tests)); then extra=(clang-15 rocm-device-libs groff-base); fi
scripts/install_packages.sh "${extra[@]}"
# The Python module is built for the python3 a user types (Debian's, or one
# of pyenv's), which needs NumPy, and pytest for the tests: Debian's come from
# the packages above, another interpreter's from PyPI. NumPy 1: Debian 12's
# pybind11 (2.10) predates NumPy 2's array API.
python="$(python3 -c 'import sys; print(sys.executable)')"
"$python" -c "import numpy, sys; sys.exit(numpy.__version__ >= '2')" 2>/dev/null ||
  "$python" -m pip install -q "numpy<2"
if ((tests)); then "$python" -c "import pytest" 2>/dev/null || "$python" -m pip install -q pytest; fi
# Denoising (render --denoise, render(denoise=True)) opens Intel Open Image
# Denoise at run time: Debian 12 packages none, so PyPI's pyoidn wheel, which
# bundles libOpenImageDenoise.so.2 (2.5.1, CPU device), goes into a virtual
# environment of the build's own, build/oidn-venv, where the renderer looks
# (host/image/denoiser.h). Without a network the rest goes on and --denoise
# says it is missing.
oidn_venv=build/oidn-venv
if ! compgen -G "$oidn_venv/lib/python3*/site-packages/pyoidn/oidn/lib/libOpenImageDenoise.so.2" >/dev/null; then
  if "$python" -m venv "$oidn_venv" >/dev/null 2>&1 &&
     "$oidn_venv/bin/python" -m pip install -q --no-deps --disable-pip-version-check "pyoidn==2.5.1.0" >/dev/null 2>&1
  then
    echo "scripts/setup.sh: Open Image Denoise (pyoidn 2.5.1.0) installed in $oidn_venv for --denoise"
  else
    rm -rf "$oidn_venv"
    echo "scripts/setup.sh: warning: could not install pyoidn into $oidn_venv (no network?): --denoise will say it is missing" >&2
  fi
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE="$python"
cmake --build build --target wavefront wavefront_python -j"$(nproc)"
# `import wavefront` from anywhere: a .pth file in the interpreter's
# site-packages names build/python (the user's own site-packages where that
# one is not writable).
site="$("$python" -c 'import sysconfig; print(sysconfig.get_path("purelib"))')"
mkdir -p "$site" 2>/dev/null || true
[ -w "$site" ] || site="$("$python" -m site --user-site)" && mkdir -p "$site"
echo "$PWD/build/python" > "$site/wavefront.pth"
if ((tests)); then cmake --build build -j"$(nproc)"; fi
