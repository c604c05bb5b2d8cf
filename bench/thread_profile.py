#!/usr/bin/env python3
"""Where rcache's threads wait, from one `perf record` of a render at 2 threads: per phase (cache
fill, final pass), the CPU samples of the main thread (M), the worker (W) and PoCL's own threads
(P), and the functions the main thread runs that the worker does not (its serial parts).

A load-independent companion to thread_speedup.py (which times 1 against 2 threads and needs a quiet
machine): CPU samples do not depend on how long the threads waited for a core. The estimate of the
2-thread speed-up of a phase is (M + W + P) / (M + P/2) — at -t 1 everything runs on one core
(PoCL's kernel threads are limited to -t since the tenth session; before, the formula was
(M + W + P/2) / (M + P/2) because PoCL used every core at any -t), at -t 2 the main thread's own
samples and half the kernel work remain — an upper bound, since waits for the worker at the end of
each parallel loop are not samples. On a loaded machine the worker starts its share of each loop
late, so the main thread does more of it and the estimate is low, not high. thread_speedup.py
--estimate is the steadier measure (CPU time split at 1 thread, from the renderer's statistics).

Phases are told apart by symbols: the fill from the first sample in CacheEngine/RadianceCache, the
final pass from the first sample in FinalPass. Needs perf and a build with symbols (Release has them).

Usage (repository root): python3 bench/thread_profile.py [--rcache build/rcache] [--top 12] SCENE.xml [rcache args...]
"""
import argparse
import collections
import os
import subprocess
import tempfile


def samples(exe, scene, extra, work):
    data = os.path.join(work, "perf.data")
    subprocess.run(["perf", "record", "-q", "-F", "1999", "-o", data, exe, scene, "-t", "2", "--quiet",
                    "-o", os.path.join(work, "out.exr")] + extra, check=True, stdout=subprocess.DEVNULL)
    out = subprocess.run(["perf", "script", "-i", data, "-F", "pid,tid,time,ip,sym"], capture_output=True,
                         text=True, check=True).stdout
    rows = []
    for line in out.splitlines():
        p = line.split(None, 3)
        if len(p) < 2 or "/" not in p[0]:
            continue
        pid, tid = p[0].split("/")
        rows.append((pid, tid, float(p[1].rstrip(":")), p[3] if len(p) > 3 else "?"))
    return rows


def report(rows, lo, hi, name, main, worker, top):
    count = collections.Counter()
    syms = {main: collections.Counter(), worker: collections.Counter()}
    for _, tid, t, s in rows:
        if lo <= t < hi:
            count["M" if tid == main else "W" if tid == worker else "P"] += 1
            if tid in syms:
                syms[tid][s[:90]] += 1
    m, w, p = count["M"], count["W"], count["P"]
    print("%s: samples main %d, worker %d, PoCL %d; estimated 2-thread speed-up %.2fx"
          % (name, m, w, p, (m + w + p) / max(1e-9, m + p / 2)))
    for s in sorted(syms[main], key=lambda s: syms[worker][s] - syms[main][s])[:top]:
        print("  %6d %6d  %s" % (syms[main][s], syms[worker][s], s))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rcache", default="build/rcache")
    ap.add_argument("--top", type=int, default=12, help="functions listed per phase (main minus worker samples)")
    ap.add_argument("scene")
    args, extra = ap.parse_known_args()
    with tempfile.TemporaryDirectory(prefix="rcache_threads_") as work:
        rows = samples(args.rcache, args.scene, extra, work)
    main_tid = rows[0][0]
    worker = collections.Counter(tid for _, tid, _, _ in rows if tid != main_tid).most_common(1)[0][0]
    engine = [t for _, _, t, s in rows if "CacheEngine::" in s or "RadianceCache::" in s]
    final = [t for _, _, t, s in rows if "FinalPass::" in s]
    if not engine or not final:
        raise SystemExit("no cache fill or final pass in the profile (path-traced by the pilot? try -D fallback=false)")
    print("columns: main thread samples, worker samples, function")
    report(rows, min(engine), min(final), "fill", main_tid, worker, args.top)
    report(rows, min(final), max(engine + final) + 1e-3, "final pass", main_tid, worker, args.top)


if __name__ == "__main__":
    main()
