#!/usr/bin/env bash
# Stands in for scancel / qdel: stops the session of each job id that fake_submit.sh started.
set -uo pipefail
dir=${FAKE_BATCH_DIR:?FAKE_BATCH_DIR is not set}
for job in "$@"; do
  id=${job%%.*}
  [ -f "$dir/$id.pid" ] || continue
  kill -TERM -- "-$(cat "$dir/$id.pid")" 2>/dev/null
  mv "$dir/$id.pid" "$dir/$id.cancelled"
done
exit 0
