#!/usr/bin/env bash
# Stands in for a batch system's submit command (sbatch, qsub) in tests/dask/jobqueue_test.py: runs
# the job script here, in the background, in a session of its own (so cancel can stop all of it),
# and prints a job id the way Slurm or PBS does. State (scripts, pids, logs) in $FAKE_BATCH_DIR.
# Usage: fake_submit.sh slurm|pbs [options...] JOB_SCRIPT   (dask-jobqueue passes the script last)
set -euo pipefail
kind=$1; shift
script=${!#}
dir=${FAKE_BATCH_DIR:?FAKE_BATCH_DIR is not set}
id=$$  # this process's id: unique among the jobs running at once
cp "$script" "$dir/$id.sh"  # dask-jobqueue removes its temporary script once we return
setsid bash "$dir/$id.sh" > "$dir/$id.log" 2>&1 < /dev/null &
echo $! > "$dir/$id.pid"
if [ "$kind" = slurm ]; then echo "Submitted batch job $id"; else echo "$id.fake-pbs"; fi
