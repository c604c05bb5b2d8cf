#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to an image: install, build, render the glossy Cornell box.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
build/rcache scenes/cornell_glossy.xml -o cornell_glossy.png "$@"
echo "wrote $(pwd)/cornell_glossy.png"
