#!/usr/bin/env bash
# Installs the Debian packages the project builds with (Open MPI for
# rendering over several machines; a build without it renders in one
# process), and any named as arguments (the fuzz build's clang), where
# missing. Shared by setup.sh, fuzz.sh and sanitize.sh, so each works alone on
# a fresh Debian 12.
set -euo pipefail

packages=(cmake g++ pkg-config pocl-opencl-icd ocl-icd-opencl-dev opencl-headers libglm-dev
          libopenimageio-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev libstb-dev libgtest-dev python3
          python3-matplotlib python3-numpy python3-dev python3-venv python3-pytest pybind11-dev openmpi-bin libopenmpi-dev
          help2man "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
