#!/usr/bin/env bash
# Installs the Debian packages the project needs (when missing) and builds it
# into build/. Safe to run again: it only installs and rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install_packages.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
