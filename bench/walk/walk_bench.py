#!/usr/bin/python3
"""Walk-through benchmark (issue 20): 24 frames of scenes/cornell_glossy.xml along cornell_path.json
(the camera moves for frames 0-13 and holds still from frame 14 on), rendered
  - by rcache with one cache shared across frames,
  - by rcache with every frame from scratch (--fresh-frames),
  - by the path tracer at the spp that takes the shared-cache rcache's time per frame;
then: time per frame, and temporal flicker over the still frames (per-pixel standard deviation
across frames relative to the per-pixel mean, averaged over pixels) and error against a high-spp
path-traced reference of the still view. Writes walk_results.json, a PNG strip and (with
--plot, through the bench venv's matplotlib) a plot.
Usage: bench/walk/walk_bench.py [--res 96] [--frames 24] [--rcache build/rcache] [--camera-path keys.json]
       [--results walk_results.json] [--strip docs/img/walk_strip.png]
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import rcache_dask  # noqa: E402  (read_exr)


def run(cmd):
    t = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return time.time() - t


def frames_of(stem, n):
    return np.stack([rcache_dask.read_exr("%s_%04d.exr" % (stem, f)).astype(np.float64) for f in range(n)])


def flicker(frames):
    mean = frames.mean(axis=0)
    std = frames.std(axis=0, ddof=1)
    lum_mean = mean.mean(axis=2)
    mask = lum_mean > 0.02 * lum_mean.max()
    return float((std.mean(axis=2)[mask] / lum_mean[mask]).mean())


def relmse(img, ref):
    return float(np.mean((img - ref) ** 2 / (ref ** 2 + 1e-2)))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--res", type=int, default=96)
    p.add_argument("--frames", type=int, default=24)
    p.add_argument("--still-from", type=int, default=14)
    p.add_argument("--rcache", default=os.path.join(ROOT, "build", "rcache"))
    p.add_argument("--out", default=os.path.join(HERE, "out"))
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--camera-path", default=os.path.join(HERE, "cornell_path.json"),
                   help="keyframes (cornell_dolly_in.json: a dolly 3x closer, where records get refined)")
    p.add_argument("--results", default=os.path.join(HERE, "walk_results.json"))
    p.add_argument("--strip", default=os.path.join(ROOT, "docs", "img", "walk_strip.png"))
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    scene = os.path.join(ROOT, "scenes", "cornell_glossy.xml")
    keys = os.path.abspath(a.camera_path)
    base = [a.rcache, scene, "--quiet", "-t", str(a.threads), "-D", "res=%d" % a.res, "--frames", str(a.frames),
            "--camera-path", keys]
    res = {"res": a.res, "frames": a.frames, "still_from": a.still_from}

    def walk(name, extra):
        stats = os.path.join(a.out, name + ".json")
        wall = run(base + extra + ["-o", os.path.join(a.out, name + ".exr"), "--stats", stats])
        with open(stats) as f:
            s = json.load(f)
        return wall, s

    # Interleaved: shared, fresh, shared again (the machine is shared; ratios side by side).
    shared_wall, shared = walk("shared", [])
    fresh_wall, fresh = walk("fresh", ["--fresh-frames"])
    shared_wall2, _ = walk("shared2", [])
    per_frame = lambda s: [f["time_s"] for f in s["frames_list"]]
    res["shared"] = {"wall_s": [shared_wall, shared_wall2], "time_per_frame_s": per_frame(shared),
                     "fill_s": [f["time_cache_fill_s"] for f in shared["frames_list"]],
                     "reused": [f["records_reused"] for f in shared["frames_list"]],
                     "added": [f["records_added"] for f in shared["frames_list"]],
                     "too_coarse": [f.get("records_too_coarse", 0) for f in shared["frames_list"]]}
    res["fresh"] = {"wall_s": fresh_wall, "time_per_frame_s": per_frame(fresh),
                    "fill_s": [f["time_cache_fill_s"] for f in fresh["frames_list"]],
                    "added": [f["records_added"] for f in fresh["frames_list"]]}
    # Path tracer at equal time: spp from a short probe, scaled to the shared walk's time per frame.
    target = float(np.mean(per_frame(shared)))
    probe_spp = 16
    _, probe = walk("path_probe", ["--integrator", "path", "--spp", str(probe_spp), "--frame-range", "0,2"])
    probe_t = float(np.mean(per_frame(probe)))
    spp = max(1, int(round(probe_spp * target / probe_t)))
    path_wall, path = walk("path", ["--integrator", "path", "--spp", str(spp)])
    res["path"] = {"spp": spp, "wall_s": path_wall, "time_per_frame_s": per_frame(path)}
    # Reference of the still view (frame 14 on): path tracer, many samples, one frame.
    ref_stem = os.path.join(a.out, "ref")
    run(base[:1] + [scene, "--quiet", "-t", str(a.threads), "-D", "res=%d" % a.res, "--frames", str(a.frames),
                    "--camera-path", keys, "--integrator", "path", "--spp", "2048",
                    "--frame-range", "%d,%d" % (a.frames - 1, a.frames), "-o", ref_stem + ".exr"])
    ref = rcache_dask.read_exr("%s_%04d.exr" % (ref_stem, a.frames - 1)).astype(np.float64)
    for name in ("shared", "fresh", "path"):
        fr = frames_of(os.path.join(a.out, name), a.frames)[a.still_from:]
        res[name]["flicker"] = flicker(fr)
        res[name]["relmse_still"] = float(np.mean([relmse(f, ref) for f in fr]))
    with open(a.results, "w") as f:
        json.dump(res, f, indent=1)
    # A strip of every fourth frame of the shared-cache walk, tone-mapped (sRGB, clamp).
    import OpenImageIO as oiio
    strip = np.concatenate([frames_of(os.path.join(a.out, "shared"), a.frames)[f] for f in range(0, a.frames, 4)], axis=1)
    srgb = np.where(strip <= 0.0031308, 12.92 * strip, 1.055 * np.power(np.clip(strip, 0, None), 1 / 2.4) - 0.055)
    png = np.clip(srgb * 255 + 0.5, 0, 255).astype(np.uint8)
    out = oiio.ImageOutput.create(a.strip)
    out.open(a.strip, oiio.ImageSpec(png.shape[1], png.shape[0], 3, oiio.UINT8))
    out.write_image(png)
    out.close()
    print(json.dumps({k: (v if not isinstance(v, dict) else {kk: vv for kk, vv in v.items() if not isinstance(vv, list)})
                      for k, v in res.items()}, indent=1))
    print("mean time per frame: shared %.3f s, fresh %.3f s, path %.3f s" %
          (np.mean(res["shared"]["time_per_frame_s"]), np.mean(res["fresh"]["time_per_frame_s"]),
           np.mean(res["path"]["time_per_frame_s"])))


if __name__ == "__main__":
    main()
