#!/usr/bin/python3
"""The Dask driver (scripts/rcache_dask.py) on a real local cluster: a scheduler and two worker
processes on 127.0.0.1, started here and stopped after. Checks:
  1. a tiled still (path tracer, box filter, 2x2 tiles) equals the single-process render bit for bit;
  2. a tiled rcache still (Gaussian filter: tiles overlap by the filter's reach; distributed fill,
     merge, final pass with the merged cache) equals the single-process rcache render within noise,
     with no seam: the per-column and per-row mean differences at tile borders are no larger than
     elsewhere; and its error against a path-traced reference is no larger than the single
     process's (the merged cache renders as well as one process's cache);
  3. a worker killed (SIGKILL) while it runs a task: Dask redoes the task on the other worker and
     the image is complete and equal to the single-process render;
  4. an animation: frames rendered across the workers (distributed fill over frame chunks, merge,
     final pass per frame) match the single-process walk-through within noise;
  5. a still and a walk where caching cannot pay (mirror sphere on a sharp floor: the pilot
     path-traces the single-process render): the driver makes the same decision, fills no cache, and
     its tiles / frames equal the single-process render bit for bit.
Usage: dask_driver_test.py path/to/rcache   (CTest, label "dask")
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dask_test_common import DATA, RC, ROOT, check, rcache_dask, summary  # noqa: E402


def read(path):
    return rcache_dask.read_exr(path).astype(np.float64)


def rcache(*args):
    subprocess.run([RC] + list(args), check=True, stdout=subprocess.DEVNULL)


class Cluster:
    """dask-scheduler + two dask-worker processes (no nanny: a killed worker stays dead)."""

    def __init__(self, tmp):
        self.file = os.path.join(tmp, "scheduler.json")
        env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "scripts"))
        common = ["--no-dashboard"]
        self.scheduler = subprocess.Popen(["dask-scheduler", "--host", "127.0.0.1", "--port", "0",
                                           "--scheduler-file", self.file] + common,
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
        self.workers = [subprocess.Popen(["dask-worker", "--scheduler-file", self.file, "--host", "127.0.0.1",
                                          "--nthreads", "1", "--no-nanny", "--death-timeout", "30"] + common,
                                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
                        for _ in range(2)]
        from dask.distributed import Client
        deadline = time.time() + 60
        while not os.path.exists(self.file) and time.time() < deadline:
            time.sleep(0.1)
        self.client = Client(scheduler_file=self.file, timeout=30)
        self.client.wait_for_workers(2, timeout=60)

    def restart_missing_workers(self):
        """Starts a worker for each one killed, so later checks again have two."""
        env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "scripts"))
        for i, w in enumerate(self.workers):
            if w.poll() is not None:
                self.workers[i] = subprocess.Popen(["dask-worker", "--scheduler-file", self.file, "--host", "127.0.0.1",
                                                    "--nthreads", "1", "--no-nanny", "--no-dashboard"],
                                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
        self.client.wait_for_workers(2, timeout=60)

    def close(self):
        try:
            self.client.close()
        finally:
            for p in self.workers + [self.scheduler]:
                if p.poll() is None:
                    p.terminate()
            for p in self.workers + [self.scheduler]:
                try:
                    p.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()


def seam_check(diff, borders_x, borders_y):
    """Per-column / per-row mean of the difference: at tile borders within 4 sigma of the others."""
    lum = diff.mean(axis=2)
    ok = True
    detail = []
    for axis, borders in ((0, borders_x), (1, borders_y)):
        means = lum.mean(axis=axis)
        at = set()
        for b in borders:
            at.update({b - 1, b})
        others = np.array([m for i, m in enumerate(means) if i not in at])
        limit = 4.0 * others.std() + 1e-4
        for i in at:
            if abs(means[i] - others.mean()) > limit:
                ok = False
                detail.append("axis %d index %d: %.4g (limit %.4g)" % (axis, i, means[i], limit))
    return ok, "; ".join(detail)


def main():
    tmp = tempfile.mkdtemp(prefix="rc_dask_")
    cluster = None
    try:
        cluster = Cluster(tmp)
        client = cluster.client
        path_args = ["--integrator", "path", "--seed", "5", "-t", "1", "-D", "res=32", "-D", "spp=8"]

        # 1. Tiled path-traced still, box filter: bit for bit.
        rcache(os.path.join(DATA, "tiny.xml"), "--quiet", "-o", os.path.join(tmp, "single_path.exr"), *path_args)
        work = os.path.join(tmp, "w1")
        os.makedirs(work)
        info = rcache_dask.render_still(client, RC, os.path.join(DATA, "tiny.xml"), os.path.join(tmp, "tiled_path.exr"),
                                        work, 2, 2, path_args, {"res": "32"})
        a, b = read(os.path.join(tmp, "tiled_path.exr")), read(os.path.join(tmp, "single_path.exr"))
        check("tiled_path_still_equals_single_process_bit_for_bit", a.shape == b.shape and np.array_equal(a, b),
              "shape %s vs %s, max diff %s" % (a.shape, b.shape, np.abs(a - b).max() if a.shape == b.shape else "-"))
        check("box_filter_tiles_need_no_border", info["border"] == 0, str(info))

        # 1b. Gaussian filter: the tiles' crop windows overlap by the filter's reach, so every pixel
        # gets the samples it gets in one render; only the order of the double sums differs.
        scene = os.path.join(tmp, "tiny_gauss.xml")
        with open(os.path.join(DATA, "tiny.xml")) as f:
            xml = f.read().replace('<rfilter type="box"/>', '<rfilter type="gaussian"/>')
        with open(scene, "w") as f:
            f.write(xml)
        rcache(scene, "--quiet", "-o", os.path.join(tmp, "single_gauss.exr"), *path_args)
        work = os.path.join(tmp, "w1b")
        os.makedirs(work)
        rcache_dask.render_still(client, RC, scene, os.path.join(tmp, "tiled_gauss.exr"), work, 2, 2, path_args,
                                 {"res": "32"})
        a, b = read(os.path.join(tmp, "tiled_gauss.exr")), read(os.path.join(tmp, "single_gauss.exr"))
        worst = float(np.max(np.abs(a - b) / (np.abs(b) + 1e-6)))
        check("tiled_gaussian_still_equals_single_process", worst < 1e-5, "max relative difference %.3g" % worst)

        # 2. Tiled rcache still, Gaussian filter: distributed fill, merge, final pass.
        # fallback=false: tiny.xml's sharp floor leaves the cache just under a quarter of the image, so
        # the single-process render's pilot would path-trace it, while tiles that load the merged cache
        # always cache; this test compares cache against cache.
        rc_args = ["--seed", "5", "-t", "1", "-D", "res=48", "-D", "spp=16", "-D", "rays=64", "-D", "fallback=false"]
        rcache(scene, "--quiet", "-o", os.path.join(tmp, "single_rc.exr"), *rc_args)
        work = os.path.join(tmp, "w2")
        os.makedirs(work)
        info = rcache_dask.render_still(client, RC, scene, os.path.join(tmp, "tiled_rc.exr"), work, 2, 2, rc_args,
                                        {"res": "48"})
        a, b = read(os.path.join(tmp, "tiled_rc.exr")), read(os.path.join(tmp, "single_rc.exr"))
        check("rcache_still_used_the_merged_cache", info["cache"] is not None and os.path.exists(info["cache"]), str(info))
        check("gaussian_tiles_overlap_by_the_filter_reach", info["border"] == 3, str(info))
        rel = float(np.mean((a - b) ** 2 / (b ** 2 + 1e-2)))
        check("tiled_rcache_still_matches_single_process", a.shape == b.shape and rel < 2e-3, "relMSE %.4g" % rel)
        ok, detail = seam_check(a - b, [24], [24])
        check("tiled_rcache_still_has_no_seam", ok, detail)
        # The merged cache renders as well as one process's cache: against a path-traced reference.
        # 25 % margin: both errors are mostly the shared final-pass noise (same seed); the caches
        # differ in which points the tiles' fills chose, which moves the error by a few percent.
        rcache(scene, "--quiet", "-o", os.path.join(tmp, "ref_rc.exr"), "--integrator", "path", "--seed", "77",
               "-t", "2", "-D", "res=48", "-D", "spp=1024")
        ref = read(os.path.join(tmp, "ref_rc.exr"))
        err_tiled = float(np.mean((a - ref) ** 2 / (ref ** 2 + 1e-2)))
        err_single = float(np.mean((b - ref) ** 2 / (ref ** 2 + 1e-2)))
        check("merged_cache_renders_as_well_as_one_process_cache", err_tiled <= 1.25 * err_single + 1e-5,
              "relMSE vs reference: tiled %.4g, single process %.4g" % (err_tiled, err_single))

        # 3. A worker killed mid-task: the task is redone on the other worker, the image is complete.
        work = os.path.join(tmp, "w3")
        os.makedirs(work)
        slow_args = ["--integrator", "path", "--seed", "5", "-t", "1", "-D", "res=32", "-D", "spp=512"]
        rcache(os.path.join(DATA, "tiny.xml"), "--quiet", "-o", os.path.join(tmp, "single_slow.exr"), *slow_args)
        killed = {}

        def kill_first_runner():
            log = os.path.join(work, "attempts.log")
            deadline = time.time() + 60
            while time.time() < deadline:
                if os.path.exists(log):
                    with open(log) as f:
                        lines = [l.split() for l in f if l.startswith("final_tile")]
                    if lines:
                        task, pid = lines[0][0], int(lines[0][1])
                        os.kill(pid, signal.SIGKILL)
                        killed.update(task=task, pid=pid)
                        return
                time.sleep(0.01)

        killer = threading.Thread(target=kill_first_runner)
        killer.start()
        rcache_dask.render_still(client, RC, os.path.join(DATA, "tiny.xml"), os.path.join(tmp, "tiled_slow.exr"), work,
                                 2, 1, slow_args, {"res": "32"})
        killer.join()
        with open(os.path.join(work, "attempts.log")) as f:
            attempts = [l.split() for l in f]
        redone = [l for l in attempts if killed and l[0] == killed["task"]]
        check("killed_workers_task_is_redone", len(redone) >= 2 and int(redone[-1][1]) != killed["pid"],
              "killed %s; attempts %s" % (killed, attempts))
        a, b = read(os.path.join(tmp, "tiled_slow.exr")), read(os.path.join(tmp, "single_slow.exr"))
        check("image_after_a_kill_is_complete_and_equal", np.array_equal(a, b),
              "max diff %s" % (np.abs(a - b).max() if a.shape == b.shape else a.shape))
        cluster.restart_missing_workers()

        # 4. Animation across workers vs the single-process walk-through.
        keys = os.path.join(DATA, "tiny_path.json")
        # fallback=false: as in 2, this compares cache against cache.
        walk_args = ["--seed", "5", "-t", "1", "-D", "res=24", "-D", "spp=16", "-D", "rays=64", "-D", "fallback=false"]
        rcache(scene, "--quiet", "--frames", "3", "--camera-path", keys, "-o", os.path.join(tmp, "walk.exr"), *walk_args)
        work = os.path.join(tmp, "w4")
        os.makedirs(work)
        info = rcache_dask.render_walk(client, RC, scene, os.path.join(tmp, "dwalk.exr"), work, 3, keys, 2, walk_args)
        worst = 0.0
        for f in range(3):
            a = read(os.path.join(tmp, "dwalk_%04d.exr" % f))
            b = read(os.path.join(tmp, "walk_%04d.exr" % f))
            worst = max(worst, float(np.mean((a - b) ** 2 / (b ** 2 + 1e-2))))
        check("distributed_walk_matches_single_process", worst < 2e-3 and info["cache"] is not None,
              "worst relMSE %.4g, %s" % (worst, info))

        # 5. The pilot's fallback decision holds in the distributed mode too.
        scene = os.path.join(tmp, "tiny_mirror.xml")
        with open(os.path.join(DATA, "tiny.xml")) as f:
            xml = f.read().replace('<bsdf type="diffuse" id="red"><rgb name="reflectance" value="0.7, 0.1, 0.1"/></bsdf>',
                                   '<bsdf type="conductor" id="red"/>')
        with open(scene, "w") as f:
            f.write(xml)
        fb_args = ["--seed", "5", "-t", "1", "-D", "res=32", "-D", "spp=8"]
        stats = os.path.join(tmp, "single_fb.json")
        rcache(scene, "--quiet", "-o", os.path.join(tmp, "single_fb.exr"), "--stats", stats, *fb_args)
        with open(stats) as f:
            decision = json.load(f).get("fallback", "")
        check("mirror_scene_is_path_traced_in_one_process", decision.startswith("path traced"), decision)
        work = os.path.join(tmp, "w5")
        os.makedirs(work)
        info = rcache_dask.render_still(client, RC, scene, os.path.join(tmp, "tiled_fb.exr"), work, 2, 2, fb_args,
                                        {"res": "32"})
        check("driver_follows_the_pilots_fallback", info["plan"] == "path traced" and info["cache"] is None, str(info))
        a, b = read(os.path.join(tmp, "tiled_fb.exr")), read(os.path.join(tmp, "single_fb.exr"))
        check("path_traced_tiles_equal_single_process_bit_for_bit", a.shape == b.shape and np.array_equal(a, b),
              "max diff %s" % (np.abs(a - b).max() if a.shape == b.shape else a.shape))
        # ... and for a walk: its frames render on their own, as the single-process walk's do.
        rcache(scene, "--quiet", "--frames", "2", "--camera-path", keys, "-o", os.path.join(tmp, "mwalk.exr"), *fb_args)
        work = os.path.join(tmp, "w6")
        os.makedirs(work)
        info = rcache_dask.render_walk(client, RC, scene, os.path.join(tmp, "dmwalk.exr"), work, 2, keys, 2, fb_args)
        same = all(np.array_equal(read(os.path.join(tmp, "dmwalk_%04d.exr" % f)), read(os.path.join(tmp, "mwalk_%04d.exr" % f)))
                   for f in range(2))
        check("path_traced_walk_equals_single_process_bit_for_bit",
              info["plan"] == "path traced" and info["cache"] is None and same, str(info))
    finally:
        if cluster:
            cluster.close()
        shutil.rmtree(tmp, ignore_errors=True)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
