#!/usr/bin/env python3
"""Thread speed-up of each phase: the path tracer's render, rcache's cache fill and final pass, at
1 thread and at N threads (default 2), interleaved repetitions (every repetition runs every
configuration once, in turn, so load from other processes hits them alike), minimum time of each.

Phase times are the renderer's own stats (time_render_s for --integrator path; time_cache_fill_s
and time_final_pass_s for --integrator rcache), so scene load, BVH build and image write are not
counted. Also printed: the process's CPU time over its wall time at N threads ("busy", N at best),
which shows how much of the run kept the N threads working.

--estimate: a measure that load from other processes does not distort (for a shared machine): runs
each configuration at -t 1 only and reads each phase's CPU split from the statistics (serial: the
control thread outside parallel loops; loops: inside them; span: the loops on 2 threads with equal
chunks, so a loop of few chunks counts its last one; other: PoCL's kernel thread), then predicts
the 2-thread speed-up two ways: Amdahl, (serial + loops + other) / (serial + (loops + other) / 2),
and with the loops' span, (serial + loops + other) / (serial + span + other / 2). Both are upper
bounds: they leave out waking the pool for each loop (the count of parallel loops is printed) and
chunks of unequal cost. Median of --reps runs; only for --threads 2.

Usage (repository root, after scripts/build.sh):
  python3 bench/thread_speedup.py [--threads 2] [--res 256] [--spp 16] [--reps 3] [--scenes cornell_glossy]
                                  [--integrators path rcache]
Prints a Markdown table.
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

PHASES = {"path": ["time_render_s"], "rcache": ["time_cache_fill_s", "time_final_pass_s"]}
CPU_SPLIT = {"time_render_s": "render", "time_cache_fill_s": "cache_fill", "time_final_pass_s": "final_pass"}


def run(exe, scene, integrator, threads, res, spp, work):
    stats = os.path.join(work, "stats.json")
    cmd = [exe, scene, "--integrator", integrator, "--spp", str(spp), "-D", "res=%d" % res, "-t", str(threads),
           "--quiet", "-o", os.path.join(work, "out.exr"), "--stats", stats]
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    err = proc.stderr.read()
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError("failed: %s\n%s" % (" ".join(cmd), err))
    with open(stats) as f:
        s = json.load(f)
    return s, (usage.ru_utime + usage.ru_stime) / wall


def estimate(args, root, work):
    runs = {}
    for _ in range(args.reps):
        for scene in args.scenes:
            path = os.path.join(root, "scenes", scene + ".xml")
            for integrator, keys in PHASES.items():
                s, _ = run(args.rcache, path, integrator, 1, args.res, args.spp, work)
                for k in keys:
                    phase = CPU_SPLIT[k]
                    if "cpu_%s_serial_s" % phase in s and (k in s):
                        runs.setdefault((scene, k), []).append(s)
    print("| scene | phase | serial s | loops s | span at 2 s | other s | serial share | loops | Amdahl at 2 | with span at 2 |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for scene in args.scenes:
        for integrator, keys in PHASES.items():
            for k in keys:
                if (scene, k) not in runs:
                    print("| %s | %s | — | — | — | — | — | — | not run | |" % (scene, k))
                    continue
                phase = CPU_SPLIT[k]
                rows = [(r["cpu_%s_serial_s" % phase], r["cpu_%s_loops_s" % phase], r["cpu_%s_loops_span_at_2_s" % phase],
                         r["cpu_%s_other_threads_s" % phase], r["%s_parallel_loops" % phase]) for r in runs[(scene, k)]]
                serial, loops, span, other, count = (statistics.median(col) for col in zip(*rows))
                total = serial + loops + other
                print("| %s | %s | %.3f | %.3f | %.3f | %.3f | %.1f %% | %d | %.2f× | %.2f× |" % (
                    scene, k, serial, loops, span, other, 100 * serial / total, count,
                    total / (serial + (loops + other) / 2), total / (serial + span + other / 2)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rcache", default="build/rcache")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--res", type=int, default=256)
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--scenes", nargs="*", default=["cornell_glossy"])
    ap.add_argument("--integrators", nargs="*", default=list(PHASES), choices=list(PHASES),
                    help="which integrators' phases to time (default both)")
    ap.add_argument("--estimate", action="store_true", help="CPU split at 1 thread instead of timing (see above)")
    args = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    work = tempfile.mkdtemp(prefix="rcache_threads_")
    if args.estimate:
        if args.threads != 2:
            ap.error("--estimate predicts 2 threads only")
        estimate(args, root, work)
        return
    best, busy = {}, {}
    for _ in range(args.reps):
        for scene in args.scenes:
            path = os.path.join(root, "scenes", scene + ".xml")
            for integrator, keys in PHASES.items():
                if integrator not in args.integrators:
                    continue
                for t in (1, args.threads):
                    s, b = run(args.rcache, path, integrator, t, args.res, args.spp, work)
                    for k in keys:
                        if k not in s:  # e.g. no fill: the pilot path-traced the scene
                            continue
                        key = (scene, k, t)
                        best[key] = min(best.get(key, s[k]), s[k])
                    if t == args.threads:
                        busy[(scene, integrator)] = max(busy.get((scene, integrator), 0.0), b)
    n = args.threads
    print("| scene | phase | 1 thread s | %d threads s | speed-up | busy at %d |" % (n, n))
    print("|---|---|---|---|---|---|")
    for scene in args.scenes:
        for integrator, keys in PHASES.items():
            if integrator not in args.integrators:
                continue
            for k in keys:
                if (scene, k, 1) not in best or (scene, k, n) not in best:
                    print("| %s | %s | — | — | not run (%s) | |" % (scene, k, "the pilot path-traced the scene"))
                    continue
                t1, tn = best[(scene, k, 1)], best[(scene, k, n)]
                print("| %s | %s | %.3f | %.3f | %.2f× | %.2f |" % (scene, k, t1, tn, t1 / tn, busy[(scene, integrator)]))


if __name__ == "__main__":
    main()
