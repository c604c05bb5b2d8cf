#!/usr/bin/python3
"""The Dask driver's batch-system path (rcache_dask.py --cluster slurm|pbs) end to end, without a
batch system: fake sbatch/scancel/squeue and qsub/qdel/qstat (tests/dask/fake_batch/) first on PATH
run each job script dask-jobqueue submits as a local background session, so the job script's
`dask worker` command really starts the workers and connects them to the driver's scheduler. For
Slurm and for PBS, checks:
  1. the driver submitted job scripts with the batch system's directives (#SBATCH / #PBS);
  2. the tiled still (path tracer, box filter, 2x1 tiles) equals the single-process render bit for bit;
  3. the tasks ran in the jobs' workers (attempts.log's session ids are the jobs'), and after the
     driver exits no job is left running (dask-jobqueue cancelled them through scancel / qdel).
dask-jobqueue is not packaged by Debian 12: scripts/install_dask_jobqueue.sh pip-installs it into a venv
that sees Debian's Dask ($RCACHE_DASK_VENV, default ~/.cache/rcache/dask-venv). Without it the test is
skipped (exit 77) and says so.
Usage: jobqueue_test.py path/to/rcache   (CTest, label "dask")
"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dask_test_common import DATA, HERE, RC, ROOT, check, rcache_dask, summary  # noqa: E402

VENV = os.environ.get("RCACHE_DASK_VENV",
                      os.path.join(os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")), "rcache", "dask-venv"))
PYTHON = os.path.join(VENV, "bin", "python")


def job_sessions(batch_dir):
    """Session ids of the jobs fake_submit.sh started (ID.pid; ID.cancelled once cancelled)."""
    ids = set()
    for f in os.listdir(batch_dir):
        if f.endswith(".pid") or f.endswith(".cancelled"):
            with open(os.path.join(batch_dir, f)) as fh:
                ids.add(int(fh.read()))
    return ids


def running_jobs(batch_dir):
    """Jobs with any process of their process group still alive."""
    alive = []
    for sid in sorted(job_sessions(batch_dir)):
        try:
            os.killpg(sid, 0)
            alive.append(sid)
        except ProcessLookupError:
            pass
    return alive


def run_kind(kind, directive, tmp, single):
    batch = os.path.join(tmp, kind + "_jobs")
    work = os.path.join(tmp, kind + "_work")
    os.makedirs(batch)
    out = os.path.join(tmp, kind + ".exr")
    env = dict(os.environ, PATH=os.path.join(HERE, "fake_batch") + os.pathsep + os.environ["PATH"],
               FAKE_BATCH_DIR=batch)
    cmd = [PYTHON, os.path.join(ROOT, "scripts", "rcache_dask.py"), "still", os.path.join(DATA, "tiny.xml"), "-o", out,
           "--tiles", "2x1", "--cluster", kind, "--jobs", "2", "--job-memory", "1GB", "--scheduler-host", "127.0.0.1",
           "--workdir", work, "--rcache", RC, "--"] + ARGS
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=240)
    check(kind + "_driver_exits_0", p.returncode == 0, p.stderr.strip()[-800:])
    scripts = [f for f in os.listdir(batch) if f.endswith(".sh")]
    texts = [open(os.path.join(batch, f)).read() for f in scripts]
    check(kind + "_jobs_submitted_through_the_batch_system",
          len(texts) >= 1 and all(directive in t and "dask_worker" in t for t in texts),
          "%d job scripts" % len(texts))
    if p.returncode == 0:
        a, b = rcache_dask.read_exr(out), rcache_dask.read_exr(single)
        check(kind + "_tiled_still_equals_single_process_bit_for_bit", a.shape == b.shape and np.array_equal(a, b))
    # A job's processes run in the session fake_submit.sh started for it (its id in ID.pid,
    # renamed ID.cancelled by the fake cancel command).
    jobs = job_sessions(batch)
    sessions = set()
    if os.path.exists(os.path.join(work, "attempts.log")):
        with open(os.path.join(work, "attempts.log")) as f:
            sessions = {int(l.split()[3]) for l in f if l.startswith("final_tile")}
    check(kind + "_tasks_ran_in_the_jobs_workers", p.returncode == 0 and len(sessions) >= 1 and sessions <= jobs,
          "task sessions %s, jobs %s" % (sorted(sessions), sorted(jobs)))
    deadline = time.time() + 30  # a cancelled job's worker and nanny shut down on SIGTERM
    while running_jobs(batch) and time.time() < deadline:
        time.sleep(0.2)
    left = running_jobs(batch)
    for sid in left:  # stop what the driver left behind, then report it
        os.killpg(sid, signal.SIGKILL)
    check(kind + "_no_job_left_running", not left, "still running: %s" % left)


ARGS = ["--integrator", "path", "--seed", "5", "-t", "1", "-D", "res=16", "-D", "spp=4"]


def main():
    probe = subprocess.run([PYTHON, "-c", "import dask_jobqueue"], stderr=subprocess.DEVNULL) if os.path.exists(PYTHON) else None
    if probe is None or probe.returncode != 0:
        print("SKIP: no dask-jobqueue in %s (scripts/install_dask_jobqueue.sh installs it with pip)" % VENV)
        return 77
    tmp = tempfile.mkdtemp(prefix="rc_jobqueue_")
    try:
        single = os.path.join(tmp, "single.exr")
        subprocess.run([RC, os.path.join(DATA, "tiny.xml"), "--quiet", "-o", single] + ARGS, check=True)
        run_kind("slurm", "#SBATCH", tmp, single)
        run_kind("pbs", "#PBS", tmp, single)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
