#!/usr/bin/env bash
# Hostile inputs (issue 19): each case used to crash, hang, exhaust memory or lose data. Every
# render runs under `timeout` and a virtual-memory limit, so a regression fails here instead of
# taking the machine down. docs/hostile_inputs.md lists the cases and what rcache does.
# Usage: hostile_tests.sh path/to/rcache  (run by CTest, label "cli")
set -uo pipefail
RC=$(realpath "$1")
DATA=$(cd "$(dirname "$0")/data" && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }

# bounded SECONDS -- command...: runs with a 3 GB address-space limit and a wall-clock limit.
bounded() {
  local secs=$1; shift 2
  # (-k: a render stuck inside one pixel would outlive the SIGTERM that asks it to stop)
  ( ulimit -v 3000000; exec timeout -k 5 "$secs" "$@" )
}
# Renders that must finish: exit 0, a finite image, within the limits.
expect_renders() {
  local name=$1 secs=$2; shift 3
  local err code
  err=$(bounded "$secs" -- "$RC" "$@" 2>&1 >/dev/null); code=$?
  if [ $code -ne 0 ]; then fail "$name" "exit $code: $(head -c 300 <<<"$err")"; return; fi
  pass "$name"
}
# Bad input: one line, the expected words, exit 1 (no crash, no timeout).
expect_refusal() {
  local name=$1 want=$2 secs=$3; shift 4
  local err code
  err=$(bounded "$secs" -- "$RC" "$@" 2>&1 >/dev/null); code=$?
  if [ $code -ne 1 ]; then fail "$name" "exit $code: $(head -c 300 <<<"$err")"; return; fi
  if ! grep -qF -- "$want" <<<"$err"; then fail "$name" "message lacks '$want': $err"; return; fi
  if [ "$(grep -c . <<<"$err")" -ne 1 ]; then fail "$name" "expected one line, got: $err"; return; fi
  pass "$name"
}
finite_image() { "$RC" diff "$1" "$1" --json 2>/dev/null | grep -q '"non_finite": 0'; }
add_shape() { sed "s|</scene>|$2</scene>|" "$DATA/tiny.xml" > "$1"; }
RCACHE=(--integrator rcache --device cpu -D rays=64 --quiet -t 2)

# --- 2. Non-finite coordinates: bounds and the octree ignore what no triangle can use.
printf 'v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv inf 0 0\nf 1 2 3\nf 1 3 4\nf 1 2 5\n' > inf_vertex.obj
add_shape inf_vertex.xml '<shape type="obj"><string name="filename" value="inf_vertex.obj"/><ref id="red"/></shape>'
expect_renders inf_vertex_in_dropped_face 20 -- inf_vertex.xml "${RCACHE[@]}" -o inf_vertex.exr
finite_image inf_vertex.exr && pass inf_vertex_image_finite || fail inf_vertex_image_finite "non-finite pixels"
add_shape huge_sphere.xml '<shape type="sphere"><point name="center" x="3e38" y="0" z="0"/><float name="radius" value="1e38"/><ref id="red"/></shape>'
expect_renders sphere_extent_overflows 20 -- huge_sphere.xml "${RCACHE[@]}" -o huge_sphere.exr

# --- 3. Fill loops make progress: radii below float resolution, tiny fields of view.
for fov in 1e-12 1e-20; do
  sed "s|<float name=\"fov\" value=\"45\"/>|<float name=\"fov\" value=\"$fov\"/>|" "$DATA/tiny.xml" > fov_$fov.xml
  expect_renders "tiny_fov_$fov" 20 -- fov_$fov.xml "${RCACHE[@]}" -o fov_$fov.exr
done

# --- 1. A full disk (here a file-size limit: EFBIG, like ENOSPC) never leaves a committed image:
# every written file is flushed and read back before the rename.
no_temporaries() { ! ls -A | grep -q "^\.$1\.tmp"; }
for ext in png exr hdr; do
  err=$( (ulimit -f 4; exec "$RC" "$DATA/tiny.xml" --integrator path -D res=128 --spp 1 -o full_$ext.$ext --quiet) 2>&1); code=$?
  if [ $code -eq 1 ] && [ ! -e full_$ext.$ext ] && no_temporaries full_$ext && grep -q "full_$ext.$ext" <<<"$err"; then
    pass "full_disk_$ext"
  else fail "full_disk_$ext" "exit $code, files: $(ls -A | grep full_$ext | tr '\n' ' ') $err"; fi
done
# The cache file does not fit (10 KB) but the image (1.3 KB) does: the image is kept, the error named.
err=$( (ulimit -f 6; exec "$RC" "$DATA/tiny.xml" "${RCACHE[@]}" -o kept.exr --cache-save lost.rcc) 2>&1); code=$?
if [ $code -eq 1 ] && grep -q "lost.rcc" <<<"$err" && finite_image kept.exr && [ ! -e lost.rcc ] && no_temporaries lost; then
  pass full_disk_cache_keeps_image
else fail full_disk_cache_keeps_image "exit $code: $err"; fi

# --- 4. SIGTERM is handled like SIGINT; temporaries never outlive the process.
"$RC" "$DATA/tiny.xml" --integrator path -D res=256 --spp 100000 -o term.exr --quiet -t 2 &
pid=$!
sleep 1.5
kill -TERM $pid
stop_start=$SECONDS
wait $pid; code=$?
# Stops promptly too: cancellation is checked per pixel, not per 16×16 tile of 100k samples each.
if [ $code -eq 143 ] && [ $((SECONDS - stop_start)) -le 10 ] && finite_image term.exr && no_temporaries term; then
  pass sigterm_keeps_partial_image
else fail sigterm_keeps_partial_image "exit $code after $((SECONDS - stop_start)) s"; fi
# A signal while a finished temporary awaits its rename (RC_TEST_COMMIT_DELAY_MS holds it there):
# one signal lets the write finish, a second abandons it; neither leaves a temporary.
wait_for_temporary() {
  for _ in $(seq 100); do ls -A | grep -q "^\.$1\.tmp" && return 0; sleep 0.1; done
  return 1
}
for signals in 1 2; do
  RC_TEST_COMMIT_DELAY_MS=3000 "$RC" "$DATA/tiny.xml" --integrator path -D res=8 --spp 1 -o during$signals.exr --quiet &
  pid=$!
  if wait_for_temporary during$signals; then
    kill -TERM $pid
    [ $signals -eq 2 ] && sleep 0.2 && kill -TERM $pid
  fi
  wait $pid; code=$?
  if [ $signals -eq 1 ]; then
    [ $code -eq 143 ] && finite_image during1.exr && no_temporaries during1 && pass signal_during_write_finishes \
      || fail signal_during_write_finishes "exit $code, $(ls -A | grep during1 | tr '\n' ' ')"
  else
    [ $code -eq 143 ] && [ ! -e during2.exr ] && no_temporaries during2 && pass second_signal_abandons_write \
      || fail second_signal_abandons_write "exit $code, $(ls -A | grep during2 | tr '\n' ' ')"
  fi
done
# A temporary left by a killed process (its PID runs no more) goes with the next write of the name.
touch .stale.tmp2147483646.exr .stale.tmp2147483646.rcc
if "$RC" "$DATA/tiny.xml" "${RCACHE[@]}" -o stale.exr --cache-save stale.rcc && no_temporaries stale; then
  pass stale_temporaries_removed
else fail stale_temporaries_removed "$(ls -A | grep stale | tr '\n' ' ')"; fi

# --- 9. Outputs are checked before the render, and never collide.
mkdir -p a_dir.exr a_dir.rcc
expect_refusal output_is_directory "-o a_dir.exr: is a directory" 20 -- "$DATA/tiny.xml" -o a_dir.exr
expect_refusal cache_save_is_directory "--cache-save a_dir.rcc: is a directory" 20 -- "$DATA/tiny.xml" -o c.exr --cache-save a_dir.rcc
# (a FIFO of our own, never a system device: a binary without the check would rename over it)
mkfifo a_fifo.json
expect_refusal output_is_fifo "--stats a_fifo.json: is not a regular file" 20 -- "$DATA/tiny.xml" -o f.exr --stats a_fifo.json
expect_refusal image_and_stats_collide "-o and --stats name the same file" 20 -- "$DATA/tiny.xml" -o same.exr --stats ./same.exr
expect_refusal cache_and_image_collide "-o and --cache-save name the same file" 20 -- "$DATA/tiny.xml" --cache-save same.exr -o same.exr
[ ! -e same.exr ] && pass collisions_write_nothing || fail collisions_write_nothing "same.exr written"

# --- 5. Deep nesting: a bound with file:line instead of a stack overflow.
python3 - <<'PY'
open("deep_elements.xml", "w").write('<scene version="3.0.0">' + "<shape type=\"sphere\">" * 100000 + "</shape>" * 100000 + "</scene>")
open("deep_twosided.xml", "w").write('<scene version="3.0.0">\n<shape type="sphere">\n' + '<bsdf type="twosided">' * 30000 + '<bsdf type="diffuse"/>' + "</bsdf>" * 30000 + "</shape></scene>")
PY
expect_refusal deep_elements "deep_elements.xml:1: elements nested deeper than" 20 -- deep_elements.xml -o d.exr
expect_refusal deep_twosided "deep_twosided.xml:3: elements nested deeper than" 20 -- deep_twosided.xml -o d.exr

# --- 7. Inputs that are not regular files are refused instead of read forever.
mkfifo mesh_fifo.obj
add_shape fifo_mesh.xml '<shape type="obj"><string name="filename" value="mesh_fifo.obj"/></shape>'
expect_refusal mesh_is_fifo "mesh_fifo.obj': not a regular file" 20 -- fifo_mesh.xml -o f.exr
expect_refusal cache_is_dev_zero "cannot open cache file '/dev/zero': not a regular file" 20 -- "$DATA/tiny.xml" "${RCACHE[@]}" -o z.exr --cache-load /dev/zero
expect_refusal cache_is_directory "cannot open cache file 'a_dir.rcc': it is a directory" 20 -- "$DATA/tiny.xml" "${RCACHE[@]}" -o z.exr --cache-load a_dir.rcc
expect_refusal scene_is_dev_zero "cannot open scene file '/dev/zero': not a regular file" 20 -- /dev/zero -o z.exr

# --- 10. Nothing given is silently ignored.
expect_refusal rr_depth_negative "-D rr_depth=-3" 20 -- "$DATA/tiny.xml" -D rr_depth=-3 -o x.exr
expect_refusal hide_emitters_banana "-D hide_emitters=banana" 20 -- "$DATA/tiny.xml" -D hide_emitters=banana -o x.exr
expect_refusal path_cache_save "--cache-save: only with the rcache integrator" 20 -- "$DATA/tiny.xml" --integrator path --cache-save x.rcc -o x.exr
expect_refusal path_cache_load "--cache-load: only with the rcache integrator" 20 -- "$DATA/tiny.xml" --integrator path --cache-load x.rcc -o x.exr
expect_refusal path_aov "--aov records: only with the rcache integrator" 20 -- "$DATA/tiny.xml" --integrator path --aov records -o x.exr
expect_refusal path_rcache_param "-D rays=64: 'rays' is an rcache parameter" 20 -- "$DATA/tiny.xml" --integrator path -D rays=64 -o x.exr
expect_renders a_at_its_lower_bound 20 -- "$DATA/tiny.xml" "${RCACHE[@]}" -D a=0.001 -D res=8 -o a_edge.exr
# -D max_depth overrides a max_depth the file writes literally (tiny.xml: 4): same image as the file edited.
sed 's|<integer name="max_depth" value="4"/>|<integer name="max_depth" value="1"/>|' "$DATA/tiny.xml" > depth1.xml
"$RC" "$DATA/tiny.xml" --integrator path -D max_depth=1 -o md_define.exr --quiet --seed 2 -t 2 \
  && "$RC" depth1.xml --integrator path -o md_file.exr --quiet --seed 2 -t 2
d=$("$RC" diff md_define.exr md_file.exr --json 2>&1)
python3 -c "import json,sys; sys.exit(0 if json.loads(sys.argv[1])['max_abs']==0 else 1)" "$d" 2>/dev/null \
  && pass define_overrides_literal_max_depth || fail define_overrides_literal_max_depth "$d"
# A triangle with 1e10 coordinates is not degenerate (its |cross|² overflows float, not double).
printf 'v -1e10 0 -1e10\nv 0 0 1e10\nv 1e10 0 -1e10\nf 1 2 3\n' > huge_triangle.obj
add_shape huge_triangle.xml '<shape type="obj"><string name="filename" value="huge_triangle.obj"/><ref id="red"/></shape>'
expect_renders huge_triangle 20 -- huge_triangle.xml --integrator path --quiet -t 2 -o huge_triangle.exr
finite_image huge_triangle.exr && pass huge_triangle_finite || fail huge_triangle_finite "non-finite pixels"

# --- 6. The cache's scene hash follows the envmap's pixels, not its path.
mkdir -p envA envB
"$RC" "$DATA/tiny.xml" --integrator path -D res=8 --spp 1 -o envA/sky.exr --quiet --seed 1
sed 's|</scene>|<emitter type="envmap"><string name="filename" value="sky.exr"/></emitter></scene>|' "$DATA/tiny.xml" > envA/scene.xml
cp envA/scene.xml envA/sky.exr envB/
if "$RC" envA/scene.xml "${RCACHE[@]}" -D res=8 -o envA/a.exr --cache-save envA/c.rcc \
   && "$RC" envB/scene.xml "${RCACHE[@]}" -D res=8 -o envB/b.exr --cache-load envA/c.rcc 2> envB/err; then
  pass cache_from_another_directory
else fail cache_from_another_directory "$(cat envB/err)"; fi
# The same path with other pixels: the cache is stale.
"$RC" "$DATA/tiny.xml" --integrator path -D res=8 --spp 1 -o envA/sky.exr --quiet --seed 2
expect_refusal cache_after_envmap_changed "made for another scene" 20 -- envA/scene.xml "${RCACHE[@]}" -D res=8 -o envA/c.exr --cache-load envA/c.rcc

# --- 7. A <default> chain that doubles its value is refused where it outgrows any real value.
python3 - <<'PY'
lines = ['<scene version="3.0.0">', '<default name="p0" value="xxxxxxxx"/>']
lines += ['<default name="p%d" value="$p%d$p%d"/>' % (i, i - 1, i - 1) for i in range(1, 41)]
open("doubling.xml", "w").write("\n".join(lines + ["</scene>"]))
PY
expect_refusal default_doubling_chain "doubling.xml:20:" 20 -- doubling.xml -o d.exr
# A row whose samples exceed the final pass's batch (262,144 samples, ~300 MB) is shaded in
# slices: 300,000 samples of one pixel under a 700 MB limit (a 342 MiB budget) used to be refused
# (one row × spp = 343 MiB); now it renders in ~200 MB.
err=$( (ulimit -v 700000; exec timeout -k 5 120 "$RC" "$DATA/tiny.xml" "${RCACHE[@]}" -D res=1 --spp 300000 -o huge_spp.exr) 2>&1); code=$?
[ $code -eq 0 ] && finite_image huge_spp.exr && pass huge_spp_streams || fail huge_spp_streams "exit $code: $err"
# Only a budget below one batch still refuses, up front and naming --spp.
err=$( (ulimit -v 600000; exec timeout -k 5 60 "$RC" "$DATA/tiny.xml" "${RCACHE[@]}" -D res=32 --spp 1048576 -o beyond.exr) 2>&1); code=$?
[ $code -eq 1 ] && grep -qF -- "--spp 1048576: the rcache final pass shades 262144 samples at once" <<<"$err" && [ ! -e beyond.exr ] \
  && pass spp_beyond_memory || fail spp_beyond_memory "exit $code: $err"
# A bad rcache parameter in the file is reported at its line.
sed 's|<integrator type="path"><integer name="max_depth" value="4"/></integrator>|<integrator type="rcache">\n<integer name="max_depth" value="4"/>\n<float name="a" value="-2"/></integrator>|' \
  "$DATA/tiny.xml" > bad_param.xml
expect_refusal rcache_param_file_line "bad_param.xml:7: <integrator type=\"rcache\">: parameter 'a'" 20 -- bad_param.xml --device cpu -o bp.exr

# --- 7. Thin films: records deeper than the primary level follow the square film of equal pixel
# count, not the strip's tiny pixels (a 16384×1 film made 120× the square film's records and ran
# for minutes). Their count may not exceed twice the 128×128 film's (plus a few).
sed 's|<integer name="width" value="$res"/><integer name="height" value="$res"/>|<integer name="width" value="$w"/><integer name="height" value="$h"/>|; s|<default name="res" value="16"/>|<default name="w" value="16"/><default name="h" value="16"/>|' \
  "$DATA/tiny.xml" > wh.xml
secondary_records() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['records'] - d['records_primary'])" "$1"; }
expect_renders film_128x128 60 -- wh.xml "${RCACHE[@]}" -D fallback=false -D w=128 -D h=128 --spp 1 -o square.exr --stats square.json
for wh in 16384x1 8192x2; do
  expect_renders "film_$wh" 60 -- wh.xml "${RCACHE[@]}" -D fallback=false -D w=${wh%x*} -D h=${wh#*x} --spp 1 -o thin_$wh.exr --stats thin_$wh.json
  sq=$(secondary_records square.json 2>/dev/null); th=$(secondary_records thin_$wh.json 2>/dev/null)
  if [ -n "$sq" ] && [ -n "$th" ] && [ "$th" -le $((2 * sq + 8)) ]; then pass "thin_film_records_$wh"
  else fail "thin_film_records_$wh" "secondary records: $th on $wh, $sq on 128x128"; fi
done

# --- 3. Chains of <ref>s and <include>s are bounded with file:line, not a stack overflow or an
# exponential blow-up (a BSDF evaluates every BSDF it nests, once per path through the refs).
python3 - "$DATA/tiny.xml" <<'PY'
import sys
tiny = open(sys.argv[1]).read()
head, tail = tiny.split("</scene>")[0], "</scene>"
def blends(name, n, second):
    lines = ['<bsdf type="diffuse" id="b0"/>']
    for i in range(1, n + 1):
        lines.append('<bsdf type="blendbsdf" id="b%d"><float name="weight" value="0.5"/><ref id="b%d"/>%s</bsdf>'
                     % (i, i - 1, second.replace("PREV", "b%d" % (i - 1))))
    lines.append('<shape type="sphere"><float name="radius" value="0.1"/><ref id="b%d"/></shape>' % n)
    body = head.rstrip() + "\n" + "\n".join(lines) + "\n" + tail
    open(name, "w").write(body)
blends("ref_chain.xml", 300, '<bsdf type="diffuse"/>')
blends("ref_laughs.xml", 40, '<ref id="PREV"/>')
for i in range(100):
    open("inc_%d.xml" % i, "w").write('<scene version="3.0.0">\n<include filename="inc_%d.xml"/>\n</scene>' % (i + 1))
open("inc_100.xml", "w").write('<scene version="3.0.0"/>')
open("include_chain.xml", "w").write(head.rstrip() + '\n<include filename="inc_0.xml"/>\n' + tail)
for i in range(30):
    open("twice_%d.xml" % i, "w").write('<scene version="3.0.0">\n<include filename="twice_%d.xml"/>\n<include filename="twice_%d.xml"/>\n</scene>' % (i + 1, i + 1))
open("twice_30.xml", "w").write('<scene version="3.0.0"/>')
open("include_laughs.xml", "w").write(head.rstrip() + '\n<include filename="twice_0.xml"/>\n' + tail)
PY
tiny_lines=$(($(wc -l < "$DATA/tiny.xml") - 1))
expect_refusal ref_chain "ref_chain.xml:$((tiny_lines + 129)): <bsdf type=\"blendbsdf\" id=\"b128\">: BSDFs nested deeper than 128" 20 -- ref_chain.xml -o r.exr
expect_refusal ref_billion_laughs "ref_laughs.xml:$((tiny_lines + 13)): <bsdf type=\"blendbsdf\" id=\"b12\">: one evaluation of this BSDF would visit more than 4096" 20 -- ref_laughs.xml -o r.exr
expect_refusal include_chain "inc_62.xml:2: <include>: <include>s nested deeper than 64 files" 20 -- include_chain.xml -o i.exr
expect_refusal include_billion_laughs "more than 10000 <include>s read in all" 20 -- include_laughs.xml -o i.exr
# -D values naming each other, doubling each round: bounded like <default>s.
dchain=(); for i in $(seq 1 40); do dchain+=(-D "p$i=\$p$((i - 1))\$p$((i - 1))"); done
expect_refusal define_doubling_chain "tiny.xml:11: <integer name=\"width\">: attribute 'value': parameter substitution in '\$res' does not terminate within 16 rounds" 20 -- "$DATA/tiny.xml" -D p0=xxxxxxxx "${dchain[@]}" -D 'res=$p40' -o d.exr

# --- 7. Every file rcache reads is refused when it is not a regular file (a FIFO would block
# forever in open(), /dev/zero be read forever): scene parts, meshes, images, MERL tables, paths.
for kind in serialized include envmap bitmap merl; do mkfifo "fifo_$kind"; done
add_shape fifo_serialized.xml '<shape type="serialized"><string name="filename" value="fifo_serialized"/></shape>'
add_shape fifo_include.xml '<include filename="fifo_include"/>'
add_shape fifo_envmap.xml '<emitter type="envmap"><string name="filename" value="fifo_envmap"/></emitter>'
add_shape fifo_bitmap.xml '<bsdf type="diffuse"><texture type="bitmap" name="reflectance"><string name="filename" value="fifo_bitmap"/></texture></bsdf>'
add_shape fifo_merl.xml '<bsdf type="merl"><string name="filename" value="fifo_merl"/></bsdf>'
expect_refusal serialized_is_fifo "fifo_serialized': not a regular file" 20 -- fifo_serialized.xml -o f.exr
expect_refusal include_is_fifo "fifo_include.xml:31: <include>: included file 'fifo_include': not a regular file" 20 -- fifo_include.xml -o f.exr
expect_refusal envmap_is_fifo "fifo_envmap': not a regular file" 20 -- fifo_envmap.xml -o f.exr
expect_refusal bitmap_is_fifo "fifo_bitmap': not a regular file" 20 -- fifo_bitmap.xml -o f.exr
expect_refusal merl_is_fifo "fifo_merl: not a regular file" 20 -- fifo_merl.xml -o f.exr
mkfifo path_fifo.json
expect_refusal camera_path_is_fifo "path_fifo.json': not a regular file" 20 -- "$DATA/tiny.xml" --frames 2 --camera-path path_fifo.json -o walk.exr

echo "$fails failure(s)"
[ $fails -eq 0 ]
