# Shared set-up of the CLI test scripts (sourced): RC (the binary, $1), DATA, a TMP directory
# removed on exit, PASS/FAIL lines and the failure count.
set -uo pipefail
RC=$1
DATA=$(cd "$(dirname "${BASH_SOURCE[0]}")/data" && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
