#!/usr/bin/env bash
# One command for the run-time-vs-error benchmark: installs what it needs (plots, EXR→PNG), builds,
# runs bench/run_bench.py with the given arguments (e.g. --quick).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
for p in python3-matplotlib openimageio-tools; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="${missing:-} $p"
done
if [ -n "${missing:-}" ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing
fi
scripts/build.sh
# The Debian interpreter: python3-matplotlib is installed for it (a pyenv python3 on PATH lacks it).
exec /usr/bin/python3 bench/run_bench.py "$@"
