#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a full test run: install, build, run every test.
# RC_REQUIRE_OPENCL=1 makes kernel tests fail (not skip) when no OpenCL device is found.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/install_dask_jobqueue.sh
scripts/build.sh
export RC_REQUIRE_OPENCL=1
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600
build/rcache verify --device opencl
# ASan+UBSan build of the parser, core and SH suites (incl. the 4500-case mutation fuzzer): ~3 min on
# 2 cores. The full sanitizer run (all CPU suites, ~12 min) is `scripts/run_sanitized.sh`.
RC_SAN_LABELS='^(core|sh|scene)$' scripts/run_sanitized.sh
