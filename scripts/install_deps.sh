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

# dask-jobqueue (the Dask driver's --cluster slurm|pbs and tests/dask/jobqueue_test.py) is not a Debian 12
# package: pip installs it into a venv that sees Debian's Dask (--system-site-packages; --no-deps so pip
# leaves the distribution's dask and distributed as they are), once; later runs find it and touch nothing.
venv="${RCACHE_DASK_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/rcache/dask-venv}"
if ! "$venv/bin/python" -c "import dask_jobqueue" 2>/dev/null; then
  echo "installing: dask-jobqueue 0.9.0 into $venv (pip)" >&2
  { /usr/bin/python3 -m venv --system-site-packages "$venv" &&
    "$venv/bin/pip" install -q --no-deps "dask-jobqueue==0.9.0"; } ||
    echo "install_deps: warning: no dask-jobqueue (pip failed); the jobqueue test will be skipped" >&2
fi
