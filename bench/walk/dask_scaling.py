#!/usr/bin/python3
"""1 vs 2 Dask worker processes (issue 20): a still of scenes/cornell_glossy.xml as 2x2 tiles and a
24-frame walk-through (cornell_path.json), each on a local cluster of N single-threaded workers
(rcache -t 1 per task), interleaved N = 1, 2, 1, 2 on this shared machine; per phase (fill, merge,
final, assemble) wall times. Writes dask_scaling.json.
Usage: bench/walk/dask_scaling.py [--res 512] [--walk-res 96] [--frames 24]
"""
import argparse
import json
import os
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import rcache_dask  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--res", type=int, default=512)
    p.add_argument("--walk-res", type=int, default=96)
    p.add_argument("--frames", type=int, default=24)
    p.add_argument("--rounds", type=int, default=1)
    a = p.parse_args()
    from dask.distributed import Client, LocalCluster
    rc = os.path.join(ROOT, "build", "rcache")
    scene = os.path.join(ROOT, "scenes", "cornell_glossy.xml")
    keys = os.path.join(HERE, "cornell_path.json")
    out = os.path.join(HERE, "out_dask")
    results = []
    for _ in range(a.rounds):
        for n in (1, 2):
            shutil.rmtree(out, ignore_errors=True)
            os.makedirs(out)
            with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None) as cl, \
                    Client(cl) as client:
                t = time.time()
                still = rcache_dask.render_still(client, rc, scene, os.path.join(out, "still.exr"), out, 2, 2,
                                                 ["-t", "1", "-D", "res=%d" % a.res], {"res": str(a.res)})
                still_s = time.time() - t
                os.makedirs(os.path.join(out, "walk"))
                t = time.time()
                walk = rcache_dask.render_walk(client, rc, scene, os.path.join(out, "walk.exr"),
                                               os.path.join(out, "walk"), a.frames, keys, n,
                                               ["-t", "1", "-D", "res=%d" % a.walk_res])
                walk_s = time.time() - t
            r = {"workers": n, "still_s": round(still_s, 2), "still_phases_s": still["times_s"],
                 "walk_s": round(walk_s, 2), "walk_phases_s": walk["times_s"]}
            print(json.dumps(r), flush=True)
            results.append(r)
    with open(os.path.join(HERE, "dask_scaling.json"), "w") as f:
        json.dump({"res": a.res, "walk_res": a.walk_res, "frames": a.frames, "runs": results}, f, indent=1)


if __name__ == "__main__":
    main()
