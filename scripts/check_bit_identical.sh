#!/usr/bin/env bash
# Shows that a restructuring left the images bit-identical: renders every shipped scene (scenes/*.xml)
# at a small size and few samples with a fixed seed, with both integrators, plus the rcache paths
# that plain renders do not reach (adaptive rounds, AOVs, --cache-save then --cache-load, the
# OpenCL backend), and hashes the output files (EXR pixel data and the cache file's bytes).
#
#   scripts/check_bit_identical.sh record BUILD_DIR HASH_FILE   # before the change
#   scripts/check_bit_identical.sh check  BUILD_DIR HASH_FILE   # after: exit 1 on any difference
#
# The hashes belong to one machine and compiler (float rounding), so they are recorded from the
# build before the change and checked against the build after it, not committed.
set -euo pipefail
mode=${1:?usage: $0 record|check BUILD_DIR HASH_FILE}
build=${2:?missing BUILD_DIR}
hashes=${3:?missing HASH_FILE}
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="$build/rcache"
[ -x "$bin" ] || { echo "no rcache binary in $build" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

common=(--quiet --seed 7 -D res=48 -D spp=4 -t 2)
render() {  # name, then rcache arguments
  local name=$1; shift
  "$bin" "$@" "${common[@]}" -o "$work/$name.exr" >/dev/null
}

for scene in "$root"/scenes/*.xml; do
  s=$(basename "$scene" .xml)
  render "$s.rcache" "$scene" --integrator rcache --device cpu
  render "$s.path" "$scene" --integrator path
done
glossy="$root/scenes/cornell_glossy.xml"
render adaptive "$glossy" --integrator rcache --device cpu --adaptive 0.05 --max-spp 16
render aovs "$glossy" --integrator rcache --device cpu --aov records,radius,technique,contributors
render save "$glossy" --integrator rcache --device cpu --cache-save "$work/cache.rcc"
render load "$glossy" --integrator rcache --device cpu --cache-load "$work/cache.rcc"
render record_frame "$glossy" --integrator rcache --device cpu -D frame=record -D mode=tl
render adaptive_caching "$glossy" --integrator rcache --device cpu -D adaptive=true -D share_pixel=false
render no_gradients "$root/scenes/cornell_diffuse.xml" --integrator rcache --device cpu -D gradients=false -D adaptive=true
RC_CACHE_DIR="$work/fresh_tables" render fresh_tables "$glossy" --integrator rcache --device cpu  # tables built, not loaded
render path_adaptive "$glossy" --integrator path --adaptive 0.05 --max-spp 16
if "$bin" devices 2>/dev/null | grep -q "^opencl:"; then
  render opencl "$glossy" --integrator rcache --device opencl
fi

(cd "$work" && sha256sum -- *.exr cache.rcc) > "$work/hashes.txt"
if [ "$mode" = record ]; then
  cp "$work/hashes.txt" "$hashes"
  echo "recorded $(wc -l < "$hashes") hashes to $hashes"
elif diff "$hashes" "$work/hashes.txt"; then
  echo "bit-identical: $(wc -l < "$hashes") outputs"
else
  echo "DIFFERENT (lines above: < recorded, > now)" >&2
  exit 1
fi
