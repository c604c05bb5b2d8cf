#!/usr/bin/env bash
# Builds with AddressSanitizer + UndefinedBehaviorSanitizer (RC_SANITIZE=ON) into build-asan/ and
# runs ctest there. Any ASan/UBSan report fails the test that triggered it (halt_on_error).
#
#   scripts/run_sanitized.sh                       # labels scene|bsdf|core|sh|cli|render (the default)
#   RC_SAN_LABELS='.*' scripts/run_sanitized.sh    # every suite (slow on 2 cores; see below)
#   RC_SAN_JOBS=4 scripts/run_sanitized.sh         # parallel build/test jobs (default: nproc)
#
# Notes (Debian 12, GCC 12, PoCL; measured outcome in bench/RESULTS.md "## Reliability"):
# - LeakSanitizer is off by default (detect_leaks=0), a precaution for PoCL/ICD-loader
#   process-lifetime allocations. Checked 2026-11-23: `rcache tests/cli/data/tiny.xml --device
#   opencl` and `--device cpu` under ASAN_OPTIONS=detect_leaks=1 report no leaks, so set
#   ASAN_OPTIONS=detect_leaks=1 to include leak checking.
# - The OpenCL suites (kernels, brdf, cache, app) are left out of the default labels: PoCL's
#   JIT-compiled kernels are not instrumented, so they add a long ASan build for little coverage.
#   Measured 2026-11-23: RC_SAN_LABELS='^(kernels|bsdf|render|brdf|cache|app|cli)$' → 217 tests
#   clean under ASan+UBSan with PoCL (11.6 min incl. build on 2 cores); with the CI subset
#   (core|sh|scene, 122 tests) that is every suite.
# - The 'cli' suite drives the rcache binary (ASan build) through its error paths and SIGINT.
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD=${RC_SAN_BUILD:-build-asan}
LABELS=${RC_SAN_LABELS:-'^(scene|bsdf|core|sh|cli|render)$'}
JOBS=${RC_SAN_JOBS:-$(nproc)}

cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRC_SANITIZE=ON -DRC_BUILD_BENCH=OFF >/dev/null

# Build only what the selected labels run (a full ASan build of every suite takes long on 2 cores).
if [[ "$LABELS" == '.*' ]]; then
  cmake --build "$BUILD" -j"$JOBS"
else
  targets=()
  for suite in core sh kernels bsdf scene render brdf cache app; do
    if [[ "$suite" =~ $LABELS && -d "tests/$suite" ]]; then targets+=("test_$suite"); fi
  done
  if [[ "cli" =~ $LABELS ]]; then targets+=(rcache); fi
  cmake --build "$BUILD" -j"$JOBS" --target "${targets[@]}"
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --test-dir "$BUILD" --output-on-failure -j"$JOBS" --timeout 900 -L "$LABELS"
