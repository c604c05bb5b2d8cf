#!/usr/bin/env bash
# Configures and builds rcache (Release) into build/. Extra arguments go to cmake's configure step.
# Where ccache is installed it compiles through it, with paths taken relative to the checkout, so
# rebuilds and other checkouts of the same sources (git worktrees) reuse the objects.
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >/dev/null
cmake --build build -j"$(nproc)"
