#!/usr/bin/env bash
# Stands in for squeue / qstat: one line per job that fake_submit.sh started and that still runs.
set -uo pipefail
dir=${FAKE_BATCH_DIR:?FAKE_BATCH_DIR is not set}
for f in "$dir"/*.pid; do
  [ -e "$f" ] || continue
  id=$(basename "$f" .pid)
  kill -0 "$(cat "$f")" 2>/dev/null && echo "$id R"
done
exit 0
