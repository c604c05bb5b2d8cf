#!/bin/sh
# rcache against Mitsuba 3 on the smoke cube (hetero_smoke.xml), both grids: SEEDS independent seeds
# of each renderer at SPP, 64², then bench/mean_agreement.py (image means and 16-px blocks).
#   bench/hetero_media/compare.sh RCACHE WORK [SEEDS] [SPP]     (from the repository root)
# Needs the bench venv's Mitsuba (llvm_ad_rgb: DRJIT_LIBLLVM_PATH set).
set -eu
RCACHE=$1 WORK=$2 SEEDS=${3:-16} SPP=${4:-256}
PY=/root/.cache/rcache/bench-venv/bin/python
HERE=$(dirname "$0")
mkdir -p "$WORK"
cp "$HERE/hetero_smoke.xml" "$WORK/"
python3 "$HERE/make_smoke_vol.py" "$WORK"
for grid in smoke smoke_rgb; do
  sed "s/value=\"smoke.vol\"/value=\"$grid.vol\"/" "$WORK/hetero_smoke.xml" > "$WORK/$grid.xml"
  r= m=
  for s in $(seq 1 "$SEEDS"); do
    [ -f "$WORK/r_${grid}_$s.exr" ] || nice -n 19 "$RCACHE" "$WORK/$grid.xml" -o "$WORK/r_${grid}_$s.exr" \
      --spp "$SPP" --seed "$s" -t 2 --quiet
    [ -f "$WORK/m_${grid}_$s.exr" ] || nice -n 19 "$PY" "$HERE/../mitsuba_render.py" "$WORK/$grid.xml" \
      "$WORK/m_${grid}_$s.exr" 64 "$SPP" "$((s + 100))" 2
    r="$r${r:+,}$WORK/r_${grid}_$s.exr" m="$m${m:+,}$WORK/m_${grid}_$s.exr"
  done
  echo "== $grid: rcache (A) against Mitsuba (B), $SEEDS seeds x $SPP spp each"
  "$PY" "$HERE/../mean_agreement.py" "$r" "$m"
done
