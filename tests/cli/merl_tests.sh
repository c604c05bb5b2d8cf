#!/usr/bin/env bash
# End-to-end: merl_generate writes a MERL file from a scene's BSDF, rcache renders a scene that
# names it (relative to the scene file), and a bad file is one located error line.
# Usage: merl_tests.sh path/to/rcache path/to/merl_generate  (run by CTest, label "cli")
set -uo pipefail
RC=$1
GEN=$2
TINY="$(cd "$(dirname "$0")/data" && pwd)/tiny.xml"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
failures=0
# check NAME COMMAND...: the command's success is the check's.
check() {
  local name=$1; shift
  if "$@"; then echo "PASS $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
size_is() { [ -f "$1" ] && [ "$(stat -c %s "$1")" -eq "$2" ]; }
# one_line_error MSG WANT...: the last command failed ($code 1..3) with one line MSG holding every WANT.
one_line_error() {
  local msg=$1; shift
  [ "$code" -ge 1 ] && [ "$code" -le 3 ] && [ "$(grep -c . <<<"$msg")" -eq 1 ] || { echo "  got ($code): $msg"; return 1; }
  for want in "$@"; do grep -qF -- "$want" <<<"$msg" || { echo "  '$want' missing in: $msg"; return 1; }; done
}

"$GEN" "$TINY" floor "$WORK/floor.binary"
check generate size_is "$WORK/floor.binary" $((12 + 3 * 90 * 90 * 180 * 8))
msg=$("$GEN" "$TINY" nope "$WORK/x.binary" 2>&1); code=$?
check generate_bad_id one_line_error "$msg" "no BSDF with id 'nope'"
"$GEN" --retro "$WORK/retro.binary"
check generate_retro size_is "$WORK/retro.binary" $((12 + 3 * 90 * 90 * 180 * 8))

# tiny.xml with its floor replaced by the twin, from a sub-folder so the path must resolve against it.
mkdir -p "$WORK/scene"
sed 's|<bsdf type="roughconductor" id="floor">|<bsdf type="merl" id="floor"><string name="filename" value="../floor.binary"/></bsdf><bsdf type="roughconductor" id="unused">|' \
  "$TINY" >"$WORK/scene/measured.xml"
for integ in path rcache; do
  "$RC" "$WORK/scene/measured.xml" -o "$WORK/$integ.exr" --integrator "$integ" --quiet
  check "render_$integ" test -s "$WORK/$integ.exr"
done

head -c 1000 "$WORK/floor.binary" >"$WORK/short.binary"
sed 's|../floor.binary|../short.binary|' "$WORK/scene/measured.xml" >"$WORK/scene/short.xml"
msg=$("$RC" "$WORK/scene/short.xml" -o "$WORK/s.exr" --quiet 2>&1); code=$?
check truncated_file one_line_error "$msg" "short.xml:" "short.binary: header says 90x90x180"
check truncated_file_no_output test ! -e "$WORK/s.exr"

[ $failures -eq 0 ] || { echo "$failures failed"; exit 1; }
