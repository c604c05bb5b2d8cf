# Shared by the CLI test scripts (sourced): the binary under test, the data folder, a temporary
# folder removed on exit, and PASS/FAIL reporting counted in $fails.
RC=$1
DATA=$(cd "$(dirname "${BASH_SOURCE[0]}")/data" && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
