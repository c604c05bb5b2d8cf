#!/usr/bin/env bash
# dask-jobqueue for the Dask driver's --cluster slurm|pbs and its test (tests/dask/jobqueue_test.py;
# run by scripts/run_tests.sh). Not a Debian 12 package: pip installs it, once, into a venv that sees
# Debian's Dask (--system-site-packages; --no-deps, so pip leaves the distribution's dask and
# distributed as they are); later runs find it and touch nothing. Without network access it warns
# and the test skips. The venv: $RCACHE_DASK_VENV, default ~/.cache/rcache/dask-venv.
set -euo pipefail
venv="${RCACHE_DASK_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/rcache/dask-venv}"
if ! "$venv/bin/python" -c "import dask_jobqueue" 2>/dev/null; then
  echo "installing: dask-jobqueue 0.9.0 into $venv (pip)" >&2
  { /usr/bin/python3 -m venv --system-site-packages "$venv" &&
    "$venv/bin/pip" install -q --no-deps "dask-jobqueue==0.9.0"; } ||
    echo "install_dask_jobqueue: warning: no dask-jobqueue (pip failed); the jobqueue test will be skipped" >&2
fi
