#!/usr/bin/env bash
# End-to-end: merl_generate writes a MERL file from a scene's BSDF, rcache renders a scene that
# names it (relative to the scene file), and a bad file is one located error line.
# Usage: merl_tests.sh path/to/rcache path/to/merl_generate  (run by CTest, label "cli")
set -uo pipefail
RC=$1
GEN=$2
DATA=$(cd "$(dirname "$0")/data" && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }

if "$GEN" "$DATA/tiny.xml" floor "$TMP/floor.binary" && [ "$(stat -c %s "$TMP/floor.binary")" -eq $((12 + 3 * 90 * 90 * 180 * 8)) ]; then
  pass generate
else
  fail generate "no file of the database's size"
fi
err=$("$GEN" "$DATA/tiny.xml" nope "$TMP/x.binary" 2>&1); code=$?
if [ $code -eq 1 ] && grep -qF "no BSDF with id 'nope'" <<<"$err"; then pass generate_bad_id; else fail generate_bad_id "exit $code: $err"; fi
if "$GEN" --retro "$TMP/retro.binary" && [ -s "$TMP/retro.binary" ]; then pass generate_retro; else fail generate_retro "no file"; fi

# tiny.xml with its floor replaced by the twin, from a sub-folder so the path must resolve against it.
mkdir -p "$TMP/scene"
sed 's|<bsdf type="roughconductor" id="floor">|<bsdf type="merl" id="floor"><string name="filename" value="../floor.binary"/></bsdf><bsdf type="roughconductor" id="unused">|' \
  "$DATA/tiny.xml" >"$TMP/scene/measured.xml"
for integ in path rcache; do
  if "$RC" "$TMP/scene/measured.xml" -o "$TMP/$integ.exr" --integrator "$integ" --quiet && [ -s "$TMP/$integ.exr" ]; then
    pass "render_$integ"
  else
    fail "render_$integ" "render failed"
  fi
done

head -c 1000 "$TMP/floor.binary" >"$TMP/short.binary"
sed 's|../floor.binary|../short.binary|' "$TMP/scene/measured.xml" >"$TMP/scene/short.xml"
err=$("$RC" "$TMP/scene/short.xml" -o "$TMP/s.exr" --quiet 2>&1); code=$?
if [ $code -ne 0 ] && [ $code -le 3 ] && grep -qF "short.xml:" <<<"$err" && grep -qF "short.binary: header says 90x90x180" <<<"$err" &&
   [ "$(grep -c . <<<"$err")" -eq 1 ] && [ ! -e "$TMP/s.exr" ]; then
  pass truncated_file
else
  fail truncated_file "exit $code: $err"
fi

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }
