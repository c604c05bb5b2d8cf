#!/usr/bin/env bash
# End-to-end tests of crop windows, walk-throughs and cache merging (issue 20): --crop and the
# hdrfilm crop parameters, --frames with --camera-path (files, one shared cache growing frame by
# frame), `rcache cache merge` (order independence, refusal of other scenes), and their errors.
# Usage: walk_tests.sh path/to/rcache  (run by CTest, label "cli")
set -uo pipefail
source "$(dirname "$0")/common.sh"
json_num() {  # file, key: the first number of "key": N
  grep -o "\"$2\": [-0-9.e+]*" "$1" | head -1 | sed 's/.*: //'
}
expect_error() {  # name, expected text, command...
  local name=$1 want=$2; shift 2
  if "$@" > "$TMP/$name.out" 2> "$TMP/$name.err"; then fail "$name" "exit 0"
  elif grep -q -- "$want" "$TMP/$name.err" && [ "$(grep -c . "$TMP/$name.err")" -eq 1 ]; then pass "$name"
  else fail "$name" "$(cat "$TMP/$name.err")"; fi
}

# Crop: the flag and the film parameters give the same image; the size is the window's.
"$RC" "$DATA/tiny.xml" --integrator path --quiet -t 2 --seed 1 --crop 3,4,9,7 -o "$TMP/crop_flag.exr" \
  --stats "$TMP/crop_flag.json" || fail crop_flag "exit $?"
[ "$(json_num "$TMP/crop_flag.json" width)" = 9 ] && [ "$(json_num "$TMP/crop_flag.json" height)" = 7 ] \
  && pass crop_image_has_window_size || fail crop_image_has_window_size "$(cat "$TMP/crop_flag.json")"
sed 's|<rfilter type="box"/>|<integer name="crop_offset_x" value="3"/><integer name="crop_offset_y" value="4"/><integer name="crop_width" value="9"/><integer name="crop_height" value="7"/><rfilter type="box"/>|' \
  "$DATA/tiny.xml" > "$TMP/crop.xml"
"$RC" "$TMP/crop.xml" --integrator path --quiet -t 2 --seed 1 -o "$TMP/crop_film.exr" || fail crop_film "exit $?"
cmp -s "$TMP/crop_flag.exr" "$TMP/crop_film.exr" && pass crop_flag_equals_film_parameters \
  || fail crop_flag_equals_film_parameters "images differ"
sed 's|<rfilter type="box"/>|<integer name="crop_offset_x" value="10"/><integer name="crop_width" value="7"/><rfilter type="box"/>|' \
  "$DATA/tiny.xml" > "$TMP/crop_bad.xml"
expect_error crop_outside_film "crop_bad.xml:[0-9]*: .*crop window 10,0 + 7x16 exceeds the film width 16" \
  "$RC" "$TMP/crop_bad.xml" -o "$TMP/x.exr" --quiet
expect_error crop_flag_outside "--crop: window 10,10 + 8x8 exceeds the film of 16x16" \
  "$RC" "$DATA/tiny.xml" --crop 10,10,8,8 -o "$TMP/x.exr" --quiet
expect_error crop_flag_malformed "--crop: expected X,Y,W,H" "$RC" "$DATA/tiny.xml" --crop 1,2,3 -o "$TMP/x.exr"
expect_error crop_flag_zero "--crop: 0 is out of range" "$RC" "$DATA/tiny.xml" --crop 1,2,0,3 -o "$TMP/x.exr"

# The pilot samples the whole sensor: a crop window (a tile) makes the full image's fallback decision.
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D res=32 --spp 1 -o "$TMP/pilot_full.exr" --stats "$TMP/pilot_full.json" || fail pilot_full "exit $?"
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D res=32 --spp 1 --crop 0,0,1,1 -o "$TMP/pilot_crop.exr" --stats "$TMP/pilot_crop.json" \
  || fail pilot_crop "exit $?"
pilotFull=$(grep -o '"fallback": "[^"]*"' "$TMP/pilot_full.json"); pilotCrop=$(grep -o '"fallback": "[^"]*"' "$TMP/pilot_crop.json")
[ -n "$pilotFull" ] && [ "$pilotFull" = "$pilotCrop" ] && pass crop_makes_the_full_images_fallback_decision \
  || fail crop_makes_the_full_images_fallback_decision "full: $pilotFull; crop: $pilotCrop"

# Walk-through: three frames, the shared cache grows (frame 0 adds every record, later frames
# reuse them and add fewer than frame 0 made). fallback=false: tiny.xml's sharp floor leaves the
# cache about a quarter of the image, where the pilot may path-trace the walk (tested below).
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D rays=32 -D fallback=false --frames 3 --camera-path "$DATA/tiny_path.json" \
  -o "$TMP/walk.exr" --stats "$TMP/walk.json" || fail walk "exit $? $(cat "$TMP/walk.json" 2>/dev/null)"
if [ -s "$TMP/walk_0000.exr" ] && [ -s "$TMP/walk_0001.exr" ] && [ -s "$TMP/walk_0002.exr" ] && [ ! -e "$TMP/walk_0003.exr" ]; then
  pass walk_writes_numbered_frames
else fail walk_writes_numbered_frames "$(ls "$TMP")"; fi
[ ! -e "$TMP/walk_walk.rcc" ] && pass walk_removes_its_cache_file || fail walk_removes_its_cache_file "left behind"
cmp -s "$TMP/walk_0000.exr" "$TMP/walk_0002.exr" && fail walk_camera_moves "frames 0 and 2 are equal" || pass walk_camera_moves
frames=$(grep -o '"frames_list": \[.*\]' "$TMP/walk.json")
added0=$(echo "$frames" | grep -o '"records_added": [0-9.e+]*' | sed -n 1p | sed 's/.*: //')
reused2=$(echo "$frames" | grep -o '"records_reused": [0-9.e+]*' | sed -n 3p | sed 's/.*: //')
added2=$(echo "$frames" | grep -o '"records_added": [0-9.e+]*' | sed -n 3p | sed 's/.*: //')
if awk -v a0="$added0" -v r2="$reused2" -v a2="$added2" 'BEGIN { exit !(a0 > 0 && r2 >= a0 && a2 < a0) }'; then
  pass walk_reuses_the_cache
else fail walk_reuses_the_cache "frame 0 added $added0; frame 2 reused $reused2, added $added2"; fi
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D rays=32 --frames 3 --camera-path "$DATA/tiny_path.json" --fresh-frames \
  -o "$TMP/fresh.exr" --stats "$TMP/fresh.json" || fail walk_fresh "exit $?"
freshReused=$(grep -o '"records_reused": [0-9.e+]*' "$TMP/fresh.json" | tail -1 | sed 's/.*: //')
[ "$freshReused" = 0 ] && pass fresh_frames_reuse_nothing || fail fresh_frames_reuse_nothing "reused $freshReused"
# One frame of the range equals the same frame of the whole path (fresh: no cache history).
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D rays=32 --frames 3 --camera-path "$DATA/tiny_path.json" --fresh-frames \
  --frame-range 2,3 -o "$TMP/range.exr" || fail walk_range "exit $?"
[ ! -e "$TMP/range_0000.exr" ] && cmp -s "$TMP/range_0002.exr" "$TMP/fresh_0002.exr" && pass frame_range_renders_that_frame \
  || fail frame_range_renders_that_frame "$(ls "$TMP")"
# A walk whose first frame the pilot path-traces (a mirror sphere on a sharp floor) shares no cache:
# every frame renders on its own, as --fresh-frames does, bit for bit.
sed 's|<bsdf type="diffuse" id="red"><rgb name="reflectance" value="0.7, 0.1, 0.1"/></bsdf>|<bsdf type="conductor" id="red"/>|' \
  "$DATA/tiny.xml" > "$TMP/mirror.xml"
"$RC" "$TMP/mirror.xml" --quiet -t 2 -D res=32 --frames 2 --camera-path "$DATA/tiny_path.json" -o "$TMP/mwalk.exr" \
  --stats "$TMP/mwalk.json" || fail mirror_walk "exit $?"
"$RC" "$TMP/mirror.xml" --quiet -t 2 -D res=32 --frames 2 --camera-path "$DATA/tiny_path.json" --fresh-frames \
  -o "$TMP/mfresh.exr" || fail mirror_walk_fresh "exit $?"
if grep -q '"cache_across_frames": "none: the first frame.s pilot path-traces"' "$TMP/mwalk.json" \
  && cmp -s "$TMP/mwalk_0000.exr" "$TMP/mfresh_0000.exr" && cmp -s "$TMP/mwalk_0001.exr" "$TMP/mfresh_0001.exr"; then
  pass walk_follows_the_pilots_fallback
else fail walk_follows_the_pilots_fallback "$(grep -o '"cache_across_frames": "[^"]*"' "$TMP/mwalk.json")"; fi
printf '{"keyframes": [\n  {"origin": [0, 1, 4]}\n]}\n' > "$TMP/bad_path.json"
expect_error camera_path_error "bad_path.json:2: keyframe needs 'target'" \
  "$RC" "$DATA/tiny.xml" --frames 2 --camera-path "$TMP/bad_path.json" -o "$TMP/x.exr" --quiet
expect_error frames_need_path "--frames and --camera-path go together" "$RC" "$DATA/tiny.xml" --frames 2 -o "$TMP/x.exr"

# Finer records for a closer camera (cache/view_refinement.h), on a diffuse floor under an open sky
# (records there are held to r_max, not by nearby geometry). A dolly toward the sphere: a small step
# (1.1x closer) skips no reused record; coming 2.5x closer skips the records whose radius exceeds
# twice this view's r_max bound, and the fill adds finer ones. A static camera adds nothing after
# frame 0. The last dolly frame agrees with a path-traced reference as well as the same frame
# rendered from scratch. At 16 spp, the base budget: below it records grow with fewer samples
# (budget_params.h), and the gradient limit then holds the floor's records below r_max near the sphere.
sed 's|<bsdf type="roughconductor" id="floor">|<bsdf type="diffuse" id="floor"><rgb name="reflectance" value="0.5"/></bsdf><bsdf type="roughconductor" id="unused">|' \
  "$DATA/tiny.xml" > "$TMP/diffuse.xml"
printf '{"keyframes": [\n  {"origin": [0, 1, 4], "target": [0, 0.5, 0], "fov": 45},\n  {"origin": [0, 0.95, 3.6], "target": [0, 0.5, 0], "fov": 45},\n  {"origin": [0, 0.8, 1.6], "target": [0, 0.5, 0], "fov": 45}\n]}\n' > "$TMP/dolly.json"
printf '{"keyframes": [\n  {"origin": [0, 1, 4], "target": [0, 0.5, 0], "fov": 45},\n  {"origin": [0, 1, 4], "target": [0, 0.5, 0], "fov": 45}\n]}\n' > "$TMP/still.json"
frame_field() {  # stats file, key, frame index (0-based): that frame's value
  grep -o '"frames_list": \[.*\]' "$1" | grep -o "\"$2\": [0-9.e+]*" | sed -n "$(($3 + 1))p" | sed 's/.*: //'
}
"$RC" "$TMP/diffuse.xml" --quiet -t 2 -D rays=32 -D res=32 --spp 16 --frames 3 --camera-path "$TMP/dolly.json" \
  -o "$TMP/dolly.exr" --stats "$TMP/dolly.json.stats" || fail walk_dolly "exit $?"
c1=$(frame_field "$TMP/dolly.json.stats" records_too_coarse 1); c2=$(frame_field "$TMP/dolly.json.stats" records_too_coarse 2)
a2=$(frame_field "$TMP/dolly.json.stats" records_added 2)
[ "$c1" = 0 ] && pass small_camera_step_keeps_reused_records || fail small_camera_step_keeps_reused_records "frame 1 skipped $c1"
awk -v c="$c2" -v a="$a2" 'BEGIN { exit !(c > 0 && a > 0) }' && pass closer_camera_adds_finer_records \
  || fail closer_camera_adds_finer_records "frame 2: $c2 records too coarse, $a2 added"
"$RC" "$TMP/diffuse.xml" --quiet -t 2 -D rays=32 -D res=32 --frames 3 --camera-path "$TMP/still.json" \
  -o "$TMP/static.exr" --stats "$TMP/static.json" || fail walk_static "exit $?"
s1=$(frame_field "$TMP/static.json" records_added 1)$(frame_field "$TMP/static.json" records_too_coarse 1)
s2=$(frame_field "$TMP/static.json" records_added 2)$(frame_field "$TMP/static.json" records_too_coarse 2)
[ "$s1$s2" = 0000 ] && pass static_camera_adds_no_records_after_frame_0 \
  || fail static_camera_adds_no_records_after_frame_0 "frames 1, 2 (added, too coarse): $s1 $s2"
"$RC" "$TMP/diffuse.xml" --quiet -t 2 -D rays=32 -D res=32 --spp 16 --frames 3 --camera-path "$TMP/dolly.json" --fresh-frames \
  --frame-range 2,3 -o "$TMP/dolly_fresh.exr" || fail walk_dolly_fresh "exit $?"
"$RC" "$TMP/diffuse.xml" --quiet -t 2 -D res=32 --integrator path --spp 1024 --frames 3 --camera-path "$TMP/dolly.json" \
  --frame-range 2,3 -o "$TMP/dolly_ref.exr" || fail walk_dolly_ref "exit $?"
errShared=$(json_num <("$RC" diff "$TMP/dolly_0002.exr" "$TMP/dolly_ref_0002.exr" --json) relmse)
errFresh=$(json_num <("$RC" diff "$TMP/dolly_fresh_0002.exr" "$TMP/dolly_ref_0002.exr" --json) relmse)
# 10 %: both errors are mostly the final pass's 16-spp noise, which the two renders share (same seed).
awk -v s="$errShared" -v f="$errFresh" 'BEGIN { exit !(s != "" && s <= 1.1 * f + 1e-4) }' \
  && pass refined_walk_frame_matches_path_tracer || fail refined_walk_frame_matches_path_tracer "relMSE shared $errShared, fresh $errFresh"

# Cache merge: two views' caches, merged in either order, give the same bytes; the merged cache
# renders (loads) like any cache file.
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D rays=32 --crop 0,0,8,16 --spp 1 --cache-save "$TMP/left.rcc" -o "$TMP/l.exr" || fail part_left "exit $?"
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D rays=32 --crop 8,0,8,16 --spp 1 --cache-save "$TMP/right.rcc" -o "$TMP/r.exr" || fail part_right "exit $?"
"$RC" cache merge "$TMP/left.rcc" "$TMP/right.rcc" -o "$TMP/lr.rcc" > "$TMP/merge.out" || fail merge "exit $?"
"$RC" cache merge "$TMP/right.rcc" "$TMP/left.rcc" -o "$TMP/rl.rcc" --quiet || fail merge_reversed "exit $?"
cmp -s "$TMP/lr.rcc" "$TMP/rl.rcc" && pass merge_is_order_independent || fail merge_is_order_independent "files differ"
grep -q "merged 2 cache files: .* records written" "$TMP/merge.out" && pass merge_reports || fail merge_reports "$(cat "$TMP/merge.out")"
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D rays=32 --cache-load "$TMP/lr.rcc" -o "$TMP/merged.exr" --stats "$TMP/merged.json" \
  && [ "$(json_num "$TMP/merged.json" records_added)" = 0 ] && pass merged_cache_serves_the_full_view \
  || fail merged_cache_serves_the_full_view "$(cat "$TMP/merged.json" 2>/dev/null | grep records)"
sed 's|value="0.7, 0.1, 0.1"|value="0.1, 0.7, 0.1"|' "$DATA/tiny.xml" > "$TMP/green.xml"
"$RC" "$TMP/green.xml" --quiet -t 2 -D rays=32 --spp 1 --cache-save "$TMP/green.rcc" -o "$TMP/g.exr" || fail part_green "exit $?"
expect_error merge_other_scene "green.rcc: cache file was made for another scene than" \
  "$RC" cache merge "$TMP/left.rcc" "$TMP/green.rcc" -o "$TMP/bad.rcc"
[ ! -e "$TMP/bad.rcc" ] && pass merge_failure_writes_nothing || fail merge_failure_writes_nothing "bad.rcc exists"
expect_error merge_needs_output "cache merge: -o C.rcc is required" "$RC" cache merge "$TMP/left.rcc"

echo "$fails failure(s)"
[ "$fails" -eq 0 ]
