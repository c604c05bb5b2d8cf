#!/usr/bin/env bash
# End-to-end CLI tests: exit codes, messages (file:line), outputs written whole or not at all.
# Usage: cli_tests.sh path/to/rcache  (run by CTest, label "cli")
set -uo pipefail
source "$(dirname "$0")/common.sh"

# expect_error NAME EXPECTED_SUBSTRING -- args...
expect_error() {
  local name=$1 want=$2; shift 3
  local err code
  err=$("$RC" "$@" 2>&1 >/dev/null); code=$?
  if [ $code -eq 0 ]; then fail "$name" "exit 0, expected failure"; return; fi
  if [ $code -gt 3 ]; then fail "$name" "exit $code (crash?): $err"; return; fi
  if ! grep -qF -- "$want" <<<"$err"; then fail "$name" "message lacks '$want': $err"; return; fi
  if [ "$(grep -c . <<<"$err")" -ne 1 ]; then fail "$name" "expected one line, got: $err"; return; fi
  pass "$name"
}

expect_error no_scene "no scene file" -- --quiet
expect_error unknown_flag "unknown option '--bogus'" -- "$DATA/tiny.xml" --bogus
expect_error bad_spp "--spp" -- "$DATA/tiny.xml" --spp -3
expect_error missing_file "nope.xml" -- "$TMP/nope.xml" -o "$TMP/a.exr"
expect_error malformed "malformed.xml:" -- "$DATA/malformed.xml" -o "$TMP/m.exr"
expect_error unknown_plugin "velvet_unicorn" -- "$DATA/unknown_plugin.xml" -o "$TMP/u.exr"
expect_error unknown_plugin_line "unknown_plugin.xml:4" -- "$DATA/unknown_plugin.xml" -o "$TMP/u.exr"
expect_error missing_mesh "does_not_exist.obj" -- "$DATA/missing_mesh.xml" -o "$TMP/mm.exr"
expect_error zero_width "width" -- "$DATA/zero_width.xml" -o "$TMP/z.exr"
expect_error bad_extension "unsupported output format" -- "$DATA/tiny.xml" -o "$TMP/out.jpg2"
expect_error unwritable "not writable" -- "$DATA/tiny.xml" -o "/proc/nope/out.exr"
expect_error bad_device "opencl:9:9" -- "$DATA/tiny.xml" --integrator rcache --device opencl:9:9 -o "$TMP/d.exr" --quiet
expect_error bad_sampler "--sampler: expected independent or ldsampler" -- "$DATA/tiny.xml" --sampler halton -o "$TMP/s.exr"
expect_error bad_adaptive "--adaptive: expected a number" -- "$DATA/tiny.xml" --adaptive lots -o "$TMP/s.exr"
expect_error zero_adaptive "--adaptive: 0 is out of range" -- "$DATA/tiny.xml" --adaptive 0 -o "$TMP/s.exr"
expect_error max_spp_alone "--max-spp: only with --adaptive" -- "$DATA/tiny.xml" --max-spp 64 -o "$TMP/s.exr"
expect_error max_spp_below "--max-spp: 4 is below --spp 16" -- "$DATA/tiny.xml" --adaptive 0.05 --spp 16 --max-spp 4 -o "$TMP/s.exr"
expect_error undefined_param "undefined_thing" -- "$DATA/tiny.xml" -o "$TMP/p.exr" -D res='$undefined_thing'
ls "$TMP"/*.exr >/dev/null 2>&1 && fail no_partial_outputs "$(ls "$TMP")" || pass no_partial_outputs

# A path-traced render writes the image and the stats JSON with the documented keys.
if "$RC" "$DATA/tiny.xml" --integrator path -o "$TMP/path.exr" --quiet --stats "$TMP/path.json" --seed 3 -t 2; then
  [ -s "$TMP/path.exr" ] && pass path_image || fail path_image "no image"
  python3 - "$TMP/path.json" <<'PY' && pass path_stats || fail path_stats "keys missing"
import json, sys
s = json.load(open(sys.argv[1]))
for k in ("time_s", "integrator", "device"):
    assert k in s, k
PY
else
  fail path_render "exit $?"
fi

# --sampler overrides the scene's <sampler> and the statistics say which one ran, for both integrators.
for integ in path rcache; do
  if "$RC" "$DATA/tiny.xml" --integrator $integ --sampler ldsampler -D rays=64 -o "$TMP/ld_$integ.exr" --quiet \
      --stats "$TMP/ld_$integ.json" -t 2; then
    python3 -c "import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))['sampler']=='ldsampler' else 1)" \
      "$TMP/ld_$integ.json" && pass "sampler_override_$integ" || fail "sampler_override_$integ" "stats: $(cat "$TMP/ld_$integ.json")"
  else
    fail "sampler_override_$integ" "exit $?"
  fi
done

# --adaptive: both integrators report it, and no pixel exceeds --max-spp.
for integ in path rcache; do
  if "$RC" "$DATA/tiny.xml" --integrator $integ --adaptive 0.05 --spp 4 --max-spp 32 -D rays=64 -o "$TMP/ad_$integ.exr" \
      --quiet --stats "$TMP/ad_$integ.json" -t 2; then
    python3 -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if s['adaptive_sampling']=='on' and 4 <= s['samples_per_pixel_mean'] <= s['samples_per_pixel_max'] <= 32 else 1)" \
      "$TMP/ad_$integ.json" && pass "adaptive_$integ" || fail "adaptive_$integ" "stats: $(cat "$TMP/ad_$integ.json")"
  else
    fail "adaptive_$integ" "exit $?"
  fi
done

# Determinism: same seed and threads → identical image.
"$RC" "$DATA/tiny.xml" --integrator path -o "$TMP/path2.exr" --quiet --seed 3 -t 2
d=$("$RC" diff "$TMP/path.exr" "$TMP/path2.exr" --json)
python3 -c "import json,sys; d=json.loads(sys.argv[1]); sys.exit(0 if d['max_abs']==0 else 1)" "$d" \
  && pass deterministic || fail deterministic "$d"

# Thread count does not change the image (per-pixel / per-item RNG streams, serial cache control flow).
for integ in path rcache; do
  "$RC" "$DATA/tiny.xml" --integrator $integ -D rays=64 -o "$TMP/t1_$integ.exr" --quiet -t 1 --seed 5
  "$RC" "$DATA/tiny.xml" --integrator $integ -D rays=64 -o "$TMP/t2_$integ.exr" --quiet -t 2 --seed 5
  d=$("$RC" diff "$TMP/t1_$integ.exr" "$TMP/t2_$integ.exr" --json)
  python3 -c "import json,sys; sys.exit(0 if json.loads(sys.argv[1])['max_abs']==0 else 1)" "$d" \
    && pass "threads_independent_$integ" || fail "threads_independent_$integ" "$d"
done

# rcache renders, its statistics name the materials' techniques.
# A scene parameter given with -D (res) reaches the scene, not the rcache integrator's parameters.
if "$RC" "$DATA/tiny.xml" --integrator rcache -D res=16 -D rays=64 -o "$TMP/rc.png" --quiet --stats "$TMP/rc.json" -t 2; then
  python3 - "$TMP/rc.json" <<'PY' && pass rcache_stats || fail rcache_stats "keys missing"
import json, sys
s = json.load(open(sys.argv[1]))
for k in ("time_s", "records", "rays", "lookups", "materials"):
    assert k in s, k
for m in s["materials"]:
    for k in ("name", "technique", "sh_order", "table_ms", "table_cache_hit"):
        assert k in m, k
PY
else
  fail rcache_render "exit $?"
fi

# The second of two identical renders takes its OpenCL programs from the disk cache of program
# binaries (when the device is OpenCL; the scalar fallback builds none).
"$RC" "$DATA/tiny.xml" --integrator rcache -D res=8 -D rays=64 --spp 1 -o "$TMP/bc1.exr" --quiet --stats "$TMP/bc1.json" -t 2 \
  && "$RC" "$DATA/tiny.xml" --integrator rcache -D res=8 -D rays=64 --spp 1 -o "$TMP/bc2.exr" --quiet --stats "$TMP/bc2.json" -t 2
python3 - "$TMP/bc2.json" <<'PY' && pass program_binary_cache || fail program_binary_cache "$(cat "$TMP/bc2.json")"
import json, sys
s = json.load(open(sys.argv[1]))
if s["device"].startswith("OpenCL"):
    assert s["kernel_programs"] > 0 and s["kernel_programs_cached"] == s["kernel_programs"], s
PY

# Without the OpenImageIO module a PNG render fails before rendering, with one message and no file;
# an EXR render does not need it.
out=$(RC_OIIO_MODULE=/nonexistent/librc_oiio_module.so "$RC" "$DATA/tiny.xml" -D res=8 --spp 1 -o "$TMP/nomod.png" --quiet 2>&1)
code=$?
if [ $code -ne 0 ] && [ ! -e "$TMP/nomod.png" ] && echo "$out" | grep -q "OpenImageIO module" \
   && [ "$(echo "$out" | wc -l)" -eq 1 ] \
   && RC_OIIO_MODULE=/nonexistent/librc_oiio_module.so "$RC" "$DATA/tiny.xml" -D res=8 --spp 1 -o "$TMP/nomod.exr" --quiet \
   && [ -s "$TMP/nomod.exr" ]; then pass openimageio_module_missing
else fail openimageio_module_missing "exit $code: $out"; fi

# A render to EXR never loads OpenImageIO (its ≈ 260 libraries cost 0.22 s per process); one to PNG
# loads it on demand and writes the file.
if LD_DEBUG=files "$RC" "$DATA/tiny.xml" -D res=8 --spp 1 -o "$TMP/nooiio.exr" --quiet 2> "$TMP/ld.log" \
   && [ -s "$TMP/nooiio.exr" ] && ! grep -q "libOpenImageIO" "$TMP/ld.log" \
   && LD_DEBUG=files "$RC" "$DATA/tiny.xml" -D res=8 --spp 1 -o "$TMP/oiio.png" --quiet 2> "$TMP/ld2.log" \
   && [ -s "$TMP/oiio.png" ] && grep -q "libOpenImageIO" "$TMP/ld2.log"; then pass openimageio_on_demand
else fail openimageio_on_demand "see $TMP/ld.log, $TMP/ld2.log"; fi

# diff --json prints the three keys; a heat map is written.
out=$("$RC" diff "$TMP/path.exr" "$TMP/path2.exr" --json --heatmap "$TMP/heat.png")
python3 -c "import json,sys; d=json.loads(sys.argv[1]); [d[k] for k in ('rmse','relmse','max_abs')]" "$out" \
  && [ -s "$TMP/heat.png" ] && pass diff_json || fail diff_json "$out"

# A kernel that fails to build: the default device falls back to the scalar path with one notice
# and renders; an explicitly requested OpenCL device fails with the build log and no image.
KROOT=$(cd "$(dirname "$0")/../../kernels" && pwd)
mkdir -p "$TMP/badk"
cp -r "$KROOT"/. "$TMP/badk/"
echo "this is not OpenCL C" >> "$TMP/badk/brdf_dot.cl"
if RC_KERNEL_DIR="$TMP/badk" "$RC" "$DATA/tiny.xml" --integrator rcache -D rays=64 -o "$TMP/kfall.exr" -t 2 \
     --stats "$TMP/kfall.json" 2> "$TMP/kfall.err" >/dev/null \
   && grep -q "notice: OpenCL device unusable" "$TMP/kfall.err" && grep -q '"device": "cpu' "$TMP/kfall.json" \
   && [ -s "$TMP/kfall.exr" ]; then pass kernel_build_fallback
else fail kernel_build_fallback "$(head -c 300 "$TMP/kfall.err")"; fi
if RC_KERNEL_DIR="$TMP/badk" "$RC" "$DATA/tiny.xml" --integrator rcache --device opencl -o "$TMP/kfail.exr" -t 2 \
     --quiet 2> "$TMP/kfail.err" >/dev/null; then fail kernel_build_explicit "exit 0"
elif grep -q "CL_BUILD_PROGRAM_FAILURE" "$TMP/kfail.err" && grep -q "brdf_dot.cl" "$TMP/kfail.err" && [ ! -e "$TMP/kfail.exr" ]; then
  pass kernel_build_explicit
else fail kernel_build_explicit "$(head -c 300 "$TMP/kfail.err")"; fi

# No OpenCL platform at all (ICD loader finds no vendor): scalar path, one notice, still renders.
if OCL_ICD_VENDORS="$TMP/no_icds" "$RC" "$DATA/tiny.xml" --integrator rcache -D rays=64 -o "$TMP/noicd.exr" -t 2 \
     2> "$TMP/noicd.err" >/dev/null && grep -q "^notice:" "$TMP/noicd.err" && [ -s "$TMP/noicd.exr" ]; then pass no_opencl_platform
else fail no_opencl_platform "$(head -c 300 "$TMP/noicd.err")"; fi

# Bad-input corpus beyond the mutation fuzzer: each case either fails with file:line and leaves no
# image, or renders a sensible (finite) image.
sed 's|<rgb name="radiance" value="10"/>|<rgb name="radiance" value="-5"/>|' "$DATA/tiny.xml" > "$TMP/neg_light.xml"
if "$RC" "$TMP/neg_light.xml" -o "$TMP/neg_light.exr" --quiet 2> "$TMP/neg_light.err"; then fail negative_light "exit 0"
elif grep -q "neg_light.xml:[0-9]*:.*non-negative" "$TMP/neg_light.err" && [ ! -e "$TMP/neg_light.exr" ]; then pass negative_light
else fail negative_light "$(cat "$TMP/neg_light.err")"; fi
sed 's|<rgb name="radiance" value="10"/>|<rgb name="radiance" value="0"/>|' "$DATA/tiny.xml" > "$TMP/zero_light.xml"
if "$RC" "$TMP/zero_light.xml" -o "$TMP/zero_light.exr" --quiet -t 2 \
   && "$RC" diff "$TMP/zero_light.exr" "$TMP/zero_light.exr" --json | grep -q '"non_finite": 0'; then pass zero_light_renders
else fail zero_light_renders "exit $?"; fi
echo "not an image" > "$TMP/not_an_image.exr"
sed "s|</scene>|<emitter type=\"envmap\"><string name=\"filename\" value=\"not_an_image.exr\"/></emitter></scene>|" \
  "$DATA/tiny.xml" > "$TMP/bad_envmap.xml"
if "$RC" "$TMP/bad_envmap.xml" -o "$TMP/bad_envmap.exr" --quiet 2> "$TMP/bad_envmap.err"; then fail envmap_not_image "exit 0"
elif grep -q "bad_envmap.xml:[0-9]*:.*envmap" "$TMP/bad_envmap.err" && [ ! -e "$TMP/bad_envmap.exr" ]; then pass envmap_not_image
else fail envmap_not_image "$(cat "$TMP/bad_envmap.err")"; fi
sed 's|origin="0, 1, 4"|origin="0, 0.6, 0.2"|' "$DATA/tiny.xml" > "$TMP/inside.xml"  # inside the sphere
if "$RC" "$TMP/inside.xml" --integrator rcache -D rays=64 -o "$TMP/inside.exr" --quiet -t 2 \
   && "$RC" diff "$TMP/inside.exr" "$TMP/inside.exr" --json | grep -q '"non_finite": 0'; then pass camera_inside_geometry
else fail camera_inside_geometry "exit $?"; fi

# Ctrl-C during a long render: exit 130 and a valid (readable) partial image.
"$RC" "$DATA/tiny.xml" --integrator path -D res=256 --spp 100000 -o "$TMP/int.exr" --quiet -t 2 &
pid=$!
sleep 1.5
kill -INT $pid
wait $pid; code=$?
if [ $code -eq 130 ] && "$RC" diff "$TMP/int.exr" "$TMP/int.exr" --json >/dev/null; then pass interrupt
else fail interrupt "exit $code"; fi

echo "$fails failure(s)"
[ $fails -eq 0 ]
