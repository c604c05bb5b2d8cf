#!/usr/bin/env bash
# Installs the Debian 12 packages rcache needs, only those missing (idempotent; no network when
# everything is present). Run as root or with sudo available.
set -euo pipefail
packages=(cmake g++ make pkg-config libembree-dev libopenimageio-dev libopenexr-dev libpugixml-dev libglm-dev zlib1g-dev
          ocl-icd-opencl-dev opencl-headers pocl-opencl-icd clinfo libgtest-dev libbenchmark-dev
          clang libclang-rt-14-dev
          python3-distributed python3-numpy python3-openimageio python3-venv)  # the Dask driver (scripts/rcache_dask.py) and its tests
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
