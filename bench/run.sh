#!/usr/bin/env bash
# One command for the run-time-vs-error benchmark: installs what it needs, builds, runs
# bench/run_bench.py with the given arguments (e.g. --quick).
#   - Debian packages: the build's (scripts/install_deps.sh), oiiotool (EXR → PNG strips), libllvm19
#     (Mitsuba 3's llvm_ad_rgb needs LLVM >= 17; LLVM 14/15 fail with "Cannot select: fminimum").
#   - A Python venv with pip's mitsuba, numpy and matplotlib, at $RCACHE_BENCH_VENV (default
#     ~/.cache/rcache/bench-venv); created once, reused while it imports mitsuba's LLVM variant.
# The product and its tests never need any of this; only the Mitsuba curve and reference do.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
missing=""
for p in openimageio-tools libllvm19 python3-venv; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing
fi
export DRJIT_LIBLLVM_PATH="${DRJIT_LIBLLVM_PATH:-/usr/lib/x86_64-linux-gnu/libLLVM-19.so}"
[ -e "$DRJIT_LIBLLVM_PATH" ] || DRJIT_LIBLLVM_PATH=$(ls /usr/lib/x86_64-linux-gnu/libLLVM-19.so* 2>/dev/null | head -1)
venv="${RCACHE_BENCH_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/rcache/bench-venv}"
if ! "$venv/bin/python" -c "import mitsuba, numpy, matplotlib; mitsuba.set_variant('llvm_ad_rgb')" 2>/dev/null; then
  echo "bench: setting up $venv (pip mitsuba numpy matplotlib)" >&2
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --upgrade pip
  "$venv/bin/pip" install -q mitsuba numpy matplotlib
fi
scripts/build.sh
exec env RCACHE_MITSUBA_PYTHON="$venv/bin/python" "$venv/bin/python" bench/run_bench.py "$@"
