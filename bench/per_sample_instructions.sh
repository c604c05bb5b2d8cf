#!/usr/bin/env bash
# Instructions per camera sample, counted by callgrind: a deterministic work count that the
# machine's load does not move (wall-clock A/B on a shared machine does), for comparing two
# builds. Scene load, BVH build and image write are left out; one thread.
#   - default: the path tracer's render loop (renderSampleBatches);
#   - FINAL=1: rcache's final pass (RcachePasses::addPass: camera rays, direct light, the cache
#     lookups, splat, adaptive rounds) with -D follow_budget=false, so the fill before it is the
#     same at every spp and only the final pass grows with it; --device cpu, so the SH kernels run
#     as the scalar backend on this thread and are counted (PoCL runs them on threads of its own).
#
#   bench/per_sample_instructions.sh BUILD/rcache [scene ...]     (default: the eight shipped scenes)
#   RES=96 SPP=8 bench/per_sample_instructions.sh ...             (the defaults)
#   FINAL=1 SPP="8 24" bench/per_sample_instructions.sh ...       (two counts: also the slope per
#                                                                  added sample, as bench/per_sample.py)
#
# Prints "scene spp instructions instructions/sample" per count, and with two counts
# "scene slope instructions/added-sample"; the callgrind files stay in $OUT (default a temp dir)
# for callgrind_annotate.
set -euo pipefail
bin=${1:?usage: $0 RCACHE_BINARY [scene ...]}
shift
root="$(cd "$(dirname "$0")/.." && pwd)"
res=${RES:-96}
read -r -a counts <<<"${SPP:-8}"
out=${OUT:-$(mktemp -d)}
mkdir -p "$out"
scenes=("$@")
if [ "${FINAL:-0}" = 1 ]; then
  toggle='*RcachePasses::addPass*'
  args=(--integrator rcache --device cpu -D follow_budget=false)
  [ ${#scenes[@]} -gt 0 ] || scenes=(corridor cornell_glossy cornell_diffuse glossy_sweep aniso_sphere curved_glossy furnace)
else
  toggle='rc::renderSampleBatches*'
  args=(--integrator path)
  [ ${#scenes[@]} -gt 0 ] || scenes=(envmap_product envmap_evening corridor cornell_glossy cornell_diffuse glossy_sweep
                                     aniso_sphere curved_glossy)
fi
for s in "${scenes[@]}"; do
  irs=()
  for spp in "${counts[@]}"; do
    log="$out/$s.$spp.log"
    valgrind --tool=callgrind --toggle-collect="$toggle" --callgrind-out-file="$out/$s.$spp.callgrind" \
      "$bin" "$root/scenes/$s.xml" -D res="$res" --spp "$spp" -t 1 "${args[@]}" --quiet -o "$out/$s.$spp.exr" >"$log" 2>&1
    ir=$(grep -o 'Collected : [0-9]*' "$log" | awk '{print $3}')
    irs+=("$ir")
    echo "$s $spp $ir $((ir / (res * res * spp)))"
  done
  if [ ${#counts[@]} -eq 2 ]; then
    echo "$s slope $(((irs[1] - irs[0]) / (res * res * (counts[1] - counts[0]))))"
  fi
done
