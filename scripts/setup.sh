#!/usr/bin/env bash
# Installs the Debian packages the project needs (when missing) and builds it
# into build/. Safe to run again: it only installs and rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ pkg-config pocl-opencl-icd ocl-icd-opencl-dev opencl-headers libglm-dev
          libopenimageio-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libgtest-dev python3
          python3-matplotlib python3-numpy)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
