#!/usr/bin/env bash
# End-to-end tests of integrator selection (app/integrator_registry.h): --integrator overriding the
# file, auto, the Mitsuba names rcache maps onto its own integrators (volpath, volpathmis, direct,
# nested aov/moment wrappers) and -D routing to integrator parameters. Equalities are byte-exact:
# the same estimator with the same seed writes the same file.
# Usage: integrator_tests.sh path/to/rcache  (run by CTest, label "cli")
set -uo pipefail
source "$(dirname "$0")/common.sh"
render() {  # output name, then arguments
  local out=$1; shift
  "$RC" "$@" --quiet --seed 3 -t 2 -o "$TMP/$out.exr" 2> "$TMP/$out.err"
}
same() {  # test name, two outputs
  if cmp -s "$TMP/$2.exr" "$TMP/$3.exr"; then pass "$1"; else fail "$1" "$2 and $3 differ"; fi
}
with_integrator() {  # file name, integrator XML replacing tiny.xml's
  sed "s|<integrator type=\"path\"><integer name=\"max_depth\" value=\"4\"/></integrator>|$2|" "$DATA/tiny.xml" > "$TMP/$1.xml"
}

render path --integrator path "$DATA/tiny.xml" || fail path "exit $?"
for alias in volpath volpathmis; do
  with_integrator $alias "<integrator type=\"$alias\"><integer name=\"max_depth\" value=\"4\"/></integrator>"
  render "$alias" "$TMP/$alias.xml" --integrator "$alias" || fail "$alias" "$(cat "$TMP/$alias.err")"
  same "${alias}_is_path" path "$alias"
done

with_integrator nested "<integrator type=\"aov\"><string name=\"aovs\" value=\"d:depth\"/><integrator type=\"moment\"><integrator type=\"path\"><integer name=\"max_depth\" value=\"4\"/></integrator></integrator></integrator>"
render nested "$TMP/nested.xml" --integrator path || fail nested "$(cat "$TMP/nested.err")"
same nested_renders_inner path nested

# direct = emitter + BSDF sample at the first hit, nothing further: the path tracer cut at depth 2.
with_integrator direct "<integrator type=\"direct\"/>"
render direct "$TMP/direct.xml" || fail direct "$(cat "$TMP/direct.err")"
render path_d2 "$DATA/tiny.xml" --integrator path -D max_depth=2 || fail path_d2 "exit $?"
same direct_is_path_to_depth_2 direct path_d2
if cmp -s "$TMP/direct.exr" "$TMP/path.exr"; then fail direct_has_no_indirect "equals max_depth 4"; else pass direct_has_no_indirect; fi

# --integrator overrides the file: a direct file rendered as path is the path image.
render override "$TMP/direct.xml" --integrator path -D max_depth=4 || fail override "$(cat "$TMP/override.err")"
same integrator_flag_overrides_file path override
"$RC" "$TMP/direct.xml" --integrator path -D max_depth=4 --quiet -t 2 -o "$TMP/override2.exr" --stats "$TMP/override.json" \
  && grep -q '"file_integrator": "direct"' "$TMP/override.json" && pass override_names_file_integrator \
  || fail override_names_file_integrator "$(cat "$TMP/override.json")"

# auto renders the file's integrator unless it is a path tracer (then rcache, the scene being cacheable).
render auto_direct "$TMP/direct.xml" --stats "$TMP/auto_direct.json" || fail auto_direct "exit $?"
same auto_keeps_direct direct auto_direct
if grep -q file_integrator "$TMP/auto_direct.json"; then fail own_integrator_not_named_twice "$(cat "$TMP/auto_direct.json")"
else pass own_integrator_not_named_twice; fi
"$RC" "$DATA/tiny.xml" --quiet -t 2 -D rays=64 -o "$TMP/auto.exr" --stats "$TMP/auto.json" \
  && grep -q '"integrator": "rcache"' "$TMP/auto.json" && pass auto_path_file_uses_rcache || fail auto_path_file_uses_rcache "$(cat "$TMP/auto.json")"

# -D naming another integrator's parameter: refused when nothing uses it, accepted when the file
# declares the name with <default> — it is then the file's $name and substitutes (here max_depth).
if "$RC" "$DATA/tiny.xml" --integrator path -D rays=2 -o "$TMP/nd.exr" --quiet 2> "$TMP/nd.err"; then fail other_param_refused "exit 0"
elif grep -q "'rays' is an rcache parameter, but this render uses the path integrator" "$TMP/nd.err"; then pass other_param_refused
else fail other_param_refused "$(cat "$TMP/nd.err")"; fi
sed -e 's|<default name="spp" value="4"/>|&<default name="rays" value="4"/>|' \
    -e 's|<integer name="max_depth" value="4"/>|<integer name="max_depth" value="$rays"/>|' "$DATA/tiny.xml" > "$TMP/declared.xml"
render declared "$TMP/declared.xml" --integrator path -D rays=2 || fail declared_default_define "$(cat "$TMP/declared.err")"
same declared_default_define_substitutes path_d2 declared

# Errors: one line with the location, non-zero exit.
with_integrator unknown "<integrator type=\"bdpt\"/>"
if "$RC" "$TMP/unknown.xml" -o "$TMP/u.exr" --quiet 2> "$TMP/u.err"; then fail unknown_integrator "exit 0"
elif grep -q "unknown.xml:5: .*unknown integrator 'bdpt'" "$TMP/u.err" && [ "$(grep -c . "$TMP/u.err")" -eq 1 ]; then pass unknown_integrator
else fail unknown_integrator "$(cat "$TMP/u.err")"; fi
with_integrator unused "<integrator type=\"path\"><float name=\"a\" value=\"0.3\"/></integrator>"
if "$RC" "$TMP/unused.xml" --integrator path -o "$TMP/un.exr" --quiet 2> "$TMP/un.err"; then fail unused_parameter "exit 0"
elif grep -q "unused.xml:5: .*unsupported parameter 'a'" "$TMP/un.err"; then pass unused_parameter
else fail unused_parameter "$(cat "$TMP/un.err")"; fi
if "$RC" "$DATA/tiny.xml" --integrator bdpt -o "$TMP/b.exr" --quiet 2> "$TMP/b.err"; then fail unknown_flag_value "exit 0"
elif grep -q "expected auto, path, volpath" "$TMP/b.err"; then pass unknown_flag_value
else fail unknown_flag_value "$(cat "$TMP/b.err")"; fi
if "$RC" "$DATA/tiny.xml" --integrator rcache -D rays=2 -o "$TMP/r.exr" --quiet 2> "$TMP/r.err"; then fail define_range "exit 0"
elif grep -q "'rays' = '2'" "$TMP/r.err"; then pass define_range
else fail define_range "$(cat "$TMP/r.err")"; fi

echo "$fails failure(s)"
[ $fails -eq 0 ]
