#!/usr/bin/env bash
# Instructions per camera sample of the path tracer's render loop, counted by callgrind: a
# deterministic work count that the machine's load does not move (wall-clock A/B on a shared
# machine does), for comparing two builds. Only renderSampleBatches is counted (scene load, BVH
# build and image write are left out), on one thread.
#
#   bench/per_sample_instructions.sh BUILD/rcache [scene ...]     (default: the eight shipped scenes)
#   RES=96 SPP=8 bench/per_sample_instructions.sh ...             (the defaults)
#
# Prints "scene instructions instructions/sample"; the callgrind files stay in $OUT (default a temp
# dir) for callgrind_annotate.
set -euo pipefail
bin=${1:?usage: $0 RCACHE_BINARY [scene ...]}
shift
root="$(cd "$(dirname "$0")/.." && pwd)"
res=${RES:-96}
spp=${SPP:-8}
out=${OUT:-$(mktemp -d)}
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(envmap_product envmap_evening corridor cornell_glossy cornell_diffuse glossy_sweep
                                   aniso_sphere curved_glossy)
for s in "${scenes[@]}"; do
  log="$out/$s.log"
  valgrind --tool=callgrind --toggle-collect='rc::renderSampleBatches*' --callgrind-out-file="$out/$s.callgrind" \
    "$bin" "$root/scenes/$s.xml" -D res="$res" --spp "$spp" -t 1 --integrator path --quiet -o "$out/$s.exr" >"$log" 2>&1
  ir=$(grep -o 'Collected : [0-9]*' "$log" | awk '{print $3}')
  echo "$s $ir $((ir / (res * res * spp)))"
done
