#!/usr/bin/env bash
# pip_install_test.sh PYTHON SOURCE WORK BINARY — `pip install .` (pyproject.toml)
# builds `import wavefront` into a fresh virtual environment, with
# Open Image Denoise (the `denoise` extra), and the module's tests pass
# against that installed copy, not build/python. Skips (77) where PyPI cannot
# be reached, since pip fetches the build backend from there.
set -euo pipefail
python=$1 source_dir=$2 work=$3 binary=$4
rm -rf "$work"
"$python" -m venv "$work/venv"
if ! "$work/venv/bin/pip" download -q --no-deps -d "$work/probe" scikit-build-core >/dev/null 2>&1; then
  echo "skipped: PyPI cannot be reached, and pip needs it for scikit-build-core"
  exit 77
fi
"$work/venv/bin/pip" install -q "$source_dir[denoise]" pytest
cd "$work" # away from the source tree and build/python
installed=$(env -u PYTHONPATH "$work/venv/bin/python" -c "import wavefront; print(wavefront.__file__)")
case "$installed" in
  "$work/venv/"*) echo "import wavefront: $installed" ;;
  *) echo "import wavefront found $installed, not the installed copy" >&2; exit 1 ;;
esac
env -u PYTHONPATH WF_BINARY="$binary" WF_REQUIRE_OIDN=1 \
  "$work/venv/bin/python" -m pytest -q -p no:cacheprovider "$source_dir/tests/python"
