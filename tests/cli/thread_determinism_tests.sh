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
[ "$fails" -eq 0 ]
