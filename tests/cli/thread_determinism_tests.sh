#!/usr/bin/env bash
# rcache's image and cache file do not depend on the thread count (issue 16): the cache's
# parallel steps (selections of points, record-ray tracing and shading, lookups, AOVs, adaptive
# caching) keep the serial order of results. Shipped scenes at a small size with enough record
# rays that every parallel step splits into several blocks; 1, 2 and 3 threads (3 splits the
# blocks unevenly on any machine).
# Usage: thread_determinism_tests.sh path/to/rcache  (run by CTest, label "cli")
set -uo pipefail
source "$(dirname "$0")/common.sh"
SCENES="$(cd "$(dirname "$0")/../../scenes" && pwd)"

same_image() {  # name, image a, image b
  local d
  d=$("$RC" diff "$2" "$3" --json) || { fail "$1" "diff failed"; return; }
  python3 -c "import json,sys; sys.exit(0 if json.loads(sys.argv[1])['max_abs']==0 else 1)" "$d" \
    && pass "$1" || fail "$1" "$d"
}

for scene in cornell_glossy corridor; do
  for t in 1 2 3; do
    "$RC" "$SCENES/$scene.xml" --integrator rcache --device cpu -D fallback=false -D res=24 -D rays=96 --spp 2 \
      -D adaptive=true --aov records,radius,contributors --seed 11 -t $t --quiet \
      -o "$TMP/${scene}_t$t.exr" --cache-save "$TMP/${scene}_t$t.rcc" \
      || fail "${scene}_render_t$t" "exit $?"
  done
  for t in 2 3; do
    same_image "${scene}_image_t1_t$t" "$TMP/${scene}_t1.exr" "$TMP/${scene}_t$t.exr"
    cmp -s "$TMP/${scene}_t1.rcc" "$TMP/${scene}_t$t.rcc" && pass "${scene}_cache_t1_t$t" \
      || fail "${scene}_cache_t1_t$t" "cache files differ"
  done
done
# -t N is N threads in all: a CPU OpenCL device (PoCL) runs its kernels on N threads too, and says
# so in the statistics; the kernels' results do not depend on it. Skipped without an OpenCL CPU
# device unless RC_REQUIRE_OPENCL=1 (CI).
if "$RC" devices 2>/dev/null | grep -q "\[CPU"; then
  for t in 1 2; do
    "$RC" "$SCENES/cornell_glossy.xml" --integrator rcache --device opencl -D fallback=false -D res=24 -D rays=96 \
      --spp 2 --seed 11 -t $t --quiet -o "$TMP/cl_t$t.exr" --stats "$TMP/cl_t$t.json" || fail "opencl_render_t$t" "exit $?"
    python3 -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if s.get('threads')==s.get('kernel_threads')==$t else 1)" \
      "$TMP/cl_t$t.json" && pass "opencl_kernel_threads_t$t" || fail "opencl_kernel_threads_t$t" "$(grep threads "$TMP/cl_t$t.json")"
  done
  same_image opencl_image_t1_t2 "$TMP/cl_t1.exr" "$TMP/cl_t2.exr"
elif [ "${RC_REQUIRE_OPENCL:-0}" = 1 ]; then
  fail opencl_kernel_threads "no OpenCL CPU device (RC_REQUIRE_OPENCL=1)"
fi
[ "$fails" -eq 0 ]
