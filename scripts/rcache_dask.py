#!/usr/bin/python3
"""Renders with rcache on a Dask cluster: one still as tiles, or a walk-through as frames.

    rcache_dask.py still SCENE.xml -o out.exr [--tiles 2x2] [--scheduler tcp://host:8786 | --local N]
    rcache_dask.py walk  SCENE.xml -o out.exr --frames N --camera-path keys.json [...]
    rcache_dask.py still SCENE.xml -o out.exr --cluster slurm|pbs --jobs N [--queue Q] [--job-memory 4GB]
    (after `--`: more rcache arguments, e.g. -- --spp 64 --integrator path)

Pipeline (rcache integrator): a distributed fill (every task fills the cache for its tile or its
chunk of frames at 1 spp and saves its records; a walk's chunks all start from frame 0's records,
so what the chunks' views share is made once; `--fill checkerboard` does the same for a still's
tile borders — half the tiles first, the others from their records — 26 % fewer records at 512²; not
the default yet: the 48² seam test flagged one border column at 4.2 sigma with it (none above 1.1
sigma at 96²), which needs more seeds to call), `rcache cache merge` of the parts (de-duplicated,
radii clamped across parts, the same file whatever the order), then the final pass of every tile
or frame with the merged cache loaded, and (stills) the tiles assembled into one EXR. Other
integrators (path) skip fill and merge, and so does a still or walk whose pilot decides, as in one
process, that caching cannot pay (render_plan): its tiles or frames are path traced.

Tiles are crop windows (hdrfilm crop_offset/crop_width semantics, `rcache --crop`) grown by the
reconstruction filter's reach, ceil(4 stddev) + 1 pixels for a Gaussian, ceil(radius) + 1 for a tent: the assembled image takes
each tile's interior only, so every pixel got all the samples it gets in one full render and no
seam appears (pixel sample streams are keyed by the sensor pixel: with the path tracer and a box
filter a tiled still equals the single-process render bit for bit).

Files move through a shared directory (--workdir, default beside the output), not through Dask:
the scene references meshes and envmaps by relative path, rcache reads them from disk, and a
cluster's workers already share a file system (NFS/Lustre) — sending a scene's whole directory tree
through the scheduler would copy gigabytes per task. Every task writes its output under a name of
its own attempt and renames it into place, so a worker killed mid-task (Dask reschedules its task
on another worker) never leaves half a file. Each attempt also leaves a line in
workdir/attempts.log (task, pid, start, session id), which the fault and jobqueue tests read.

Dask: Debian 12's python3-distributed (2022.12), installed by scripts/install_deps.sh like every
other dependency: apt is what the CI machine already uses, needs no PyPI access, and the version is
fixed with the distribution. The API used (Client, LocalCluster-free scheduler address, submit,
gather, upload_file) is stable across newer PyPI releases too. Slurm/PBS clusters: `--cluster
slurm|pbs --jobs N` starts the workers as batch jobs through dask-jobqueue (jobqueue_cluster).
"""
import argparse
import math
import os
import re
import subprocess
import sys
import time
import uuid
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_RCACHE = os.path.join(HERE, "..", "build", "rcache")


# ---- scene facts the driver needs (film size, filter reach), with <default> and -D substitution

def _substitute(text, params):
    return re.sub(r"\$(\w+)", lambda m: params.get(m.group(1), m.group(0)), text)


def film_of(scene_path, defines):
    """(width, height, border px) of the scene's film; border = the reconstruction filter's reach."""
    try:
        root = ET.parse(scene_path).getroot()
    except ET.ParseError as e:
        raise RuntimeError("%s: %s" % (scene_path, e))
    params = {d.get("name"): d.get("value") for d in root.iter("default")}
    params.update(defines)
    film = root.find("./sensor/film")
    width, height, border = 768, 576, 3  # Mitsuba's defaults, Gaussian stddev 0.5
    if film is None:
        return width, height, border
    for node in film:
        name, value = node.get("name"), node.get("value")
        if name in ("width", "height") and value is not None:
            v = int(_substitute(value, params))
            width, height = (v, height) if name == "width" else (width, v)
    rfilter = film.find("rfilter")
    if rfilter is not None and rfilter.get("type") == "box":
        border = 0
    elif rfilter is not None and rfilter.get("type") == "tent":
        border = math.ceil(_filter_param(rfilter, "radius", 1.0, 64.0, params)) + 1
    elif rfilter is not None:
        border = math.ceil(4.0 * _filter_param(rfilter, "stddev", 0.5, 16.0, params)) + 1
    return width, height, border


def _filter_param(rfilter, name, default, largest, params):
    """A reconstruction filter's float parameter; `largest` (the most rcache accepts) when unresolved."""
    for node in rfilter:
        if node.get("name") == name:
            try:
                return float(_substitute(node.get("value"), params))
            except ValueError:
                return largest
    return default


def make_tiles(width, height, tiles_x, tiles_y, border):
    """Interior windows covering the image, each with its crop window grown by `border`."""
    tiles = []
    for j in range(tiles_y):
        for i in range(tiles_x):
            x0, x1 = width * i // tiles_x, width * (i + 1) // tiles_x
            y0, y1 = height * j // tiles_y, height * (j + 1) // tiles_y
            cx0, cy0 = max(0, x0 - border), max(0, y0 - border)
            cx1, cy1 = min(width, x1 + border), min(height, y1 + border)
            tiles.append({"index": len(tiles), "x": x0, "y": y0, "w": x1 - x0, "h": y1 - y0,
                          "crop": (cx0, cy0, cx1 - cx0, cy1 - cy0)})
    return tiles


# ---- tasks (run on the workers; everything they need comes as arguments)

def _log_attempt(workdir, task):
    with open(os.path.join(workdir, "attempts.log"), "a") as f:
        f.write("%s %d %.3f %d\n" % (task, os.getpid(), time.time(), os.getsid(0)))


def _run(rcache, args):
    p = subprocess.run([rcache] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        raise RuntimeError("rcache %s: exit %d: %s" % (" ".join(args), p.returncode, p.stderr.strip()))
    return p.stdout


def _attempt_name(path):
    stem, ext = os.path.splitext(path)
    return "%s.attempt-%s%s" % (stem, uuid.uuid4().hex[:8], ext)


def fill_task(rcache, scene, crop, frames, workdir, name, extra, base=None):
    """Fills the cache for a crop window (stills) or a chunk of frames (walks) at 1 spp, on top of
    the records of `base` if given; returns the part's cache file."""
    _log_attempt(workdir, name)
    part = os.path.join(workdir, name + ".rcc")
    tmp = _attempt_name(part)
    out = os.path.join(workdir, _attempt_name(name + "_fill.exr"))
    args = [scene, "--quiet", "--spp", "1", "--cache-save", tmp, "-o", out] + extra
    if base:
        args += ["--cache-load", base] + ([] if frames else ["--cache-reuse"])
    if crop:
        args += ["--crop", "%d,%d,%d,%d" % crop]
    if frames:
        args += ["--frames", str(frames["count"]), "--camera-path", frames["path"],
                 "--frame-range", "%d,%d" % (frames["first"], frames["end"])]
    _run(rcache, args)
    for leftover in _frame_outputs(out, frames):
        if os.path.exists(leftover):
            os.remove(leftover)
    os.replace(tmp, part)
    return part


def _frame_outputs(out, frames):
    if not frames:
        return [out]
    stem, ext = os.path.splitext(out)
    return ["%s_%04d%s" % (stem, f, ext) for f in range(frames["first"], frames["end"])]


def merge_task(rcache, parts, output, workdir):
    _log_attempt(workdir, "merge_" + os.path.splitext(os.path.basename(output))[0])
    tmp = _attempt_name(output)
    _run(rcache, ["cache", "merge"] + sorted(parts) + ["-o", tmp, "--quiet"])
    os.replace(tmp, output)
    return output


def final_task(rcache, scene, crop, frame, cache, workdir, name, output, extra):
    """The final pass of one tile (crop) or one frame, with the merged cache loaded (no fill)."""
    _log_attempt(workdir, name)
    tmp = _attempt_name(output)
    args = [scene, "--quiet", "-o", tmp] + extra
    if cache:
        args += ["--cache-load", cache]
    if crop:
        args += ["--crop", "%d,%d,%d,%d" % crop]
    if frame:
        args += ["--frames", str(frame["count"]), "--camera-path", frame["path"],
                 "--frame-range", "%d,%d" % (frame["index"], frame["index"] + 1), "--fresh-frames"]
        tmp = _frame_outputs(tmp, {"first": frame["index"], "end": frame["index"] + 1})[0]
    _run(rcache, args)
    os.replace(tmp, output)
    return output


# ---- driver

def read_exr(path):
    """RGB of an image as float32 [height, width, 3] (ImageInput, not ImageBuf: ImageBuf's cache
    would serve a stale copy of a file rewritten under the same name)."""
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise RuntimeError("%s: cannot read: %s" % (path, oiio.geterror()))
    try:
        return inp.read_image(oiio.FLOAT)[:, :, :3]
    finally:
        inp.close()


def assemble(tiles, tile_files, width, height, output):
    import numpy as np
    import OpenImageIO as oiio
    full = np.zeros((height, width, 3), dtype=np.float32)
    for t, path in zip(tiles, tile_files):
        px = read_exr(path)
        cx, cy = t["crop"][0], t["crop"][1]
        ox, oy = t["x"] - cx, t["y"] - cy
        full[t["y"]:t["y"] + t["h"], t["x"]:t["x"] + t["w"]] = px[oy:oy + t["h"], ox:ox + t["w"]]
    spec = oiio.ImageSpec(width, height, 3, oiio.FLOAT)
    tmp = output + ".part.exr"
    out = oiio.ImageOutput.create(tmp)
    if out is None or not out.open(tmp, spec):
        raise RuntimeError("%s: cannot write: %s" % (output, oiio.geterror()))
    out.write_image(full)
    out.close()
    os.replace(tmp, output)


def render_plan(rcache, scene, extra, walk=None):
    """How the render runs, decided once for every tile or frame: "cache" (rcache's fill, merge,
    final pass), "path traced" (rcache's pilot found that caching cannot pay here, so tiles or frames
    render without a cache, as in one process) or "no cache" (another integrator). Asks rcache on
    one pixel at 1 spp: its pilot samples the whole sensor, not the crop window, so this is the
    decision of the full image; each tile's rcache repeats the same pilot (same grid, same seeds)
    and path-traces too. walk = (frames, camera path): the decision of the walk's first frame,
    which a single-process walk makes the same way (frames then render on their own)."""
    import json
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        stats = os.path.join(d, "s.json")
        args = [scene, "--quiet", "--spp", "1", "--crop", "0,0,1,1", "-o", os.path.join(d, "p.exr"), "--stats", stats]
        if walk:
            args += ["--frames", str(walk[0]), "--camera-path", walk[1], "--frame-range", "0,1"]
        _run(rcache, args + extra)
        with open(stats) as f:
            s = json.load(f)
    if s.get("integrator") != "rcache":
        return "no cache"
    if walk:
        return "path traced" if str(s.get("cache_across_frames", "")).startswith("none") else "cache"
    return "path traced" if str(s.get("fallback", "")).startswith("path traced") else "cache"


class _PhaseTimes:
    """Wall time of each phase (fill, merge, final, assemble): the phases are barriers anyway (the
    merge needs every part, the final pass the merged cache)."""

    def __init__(self):
        self.seconds = {}
        self._last = time.time()

    def mark(self, phase):
        now = time.time()
        self.seconds[phase] = round(now - self._last, 3)
        self._last = now

    def wait(self, phase, futures):
        from dask.distributed import wait
        wait(futures)
        for f in futures:
            if f.status == "error":
                f.result()  # raises the task's error
        self.mark(phase)


def render_still(client, rcache, scene, output, workdir, tiles_x, tiles_y, extra, defines, fill="independent"):
    """fill: "independent" (every tile fills from an empty cache: fully parallel, but both sides of a
    tile border make records there) or "checkerboard" (the "black" tiles first; the others start from
    their merged records, so borders get records once, at the price of two rounds)."""
    width, height, border = film_of(scene, defines)
    tiles = make_tiles(width, height, tiles_x, tiles_y, border)
    times = _PhaseTimes()
    cache = None
    plan = render_plan(rcache, scene, extra)
    if plan == "cache":
        def fill_tile(t, base=None):
            return client.submit(fill_task, rcache, scene, t["crop"], None, workdir, "fill_tile%d" % t["index"], extra,
                                 base, pure=False)
        if fill == "checkerboard" and len(tiles) > 1:
            black = [t for t in tiles if (t["index"] % tiles_x + t["index"] // tiles_x) % 2 == 0]
            white = [t for t in tiles if t not in black]
            black_parts = [fill_tile(t) for t in black]
            base = client.submit(merge_task, rcache, black_parts, os.path.join(workdir, "black.rcc"), workdir,
                                 pure=False)
            parts = black_parts + [fill_tile(t, base) for t in white]
        else:
            parts = [fill_tile(t) for t in tiles]
        times.wait("fill", parts)
        cache = client.submit(merge_task, rcache, parts, os.path.join(workdir, "merged.rcc"), workdir, pure=False)
        times.wait("merge", [cache])
    finals = [client.submit(final_task, rcache, scene, t["crop"], None, cache, workdir, "final_tile%d" % t["index"],
                            os.path.join(workdir, "tile%d.exr" % t["index"]), extra, pure=False) for t in tiles]
    tile_files = client.gather(finals)
    times.mark("final")
    assemble(tiles, tile_files, width, height, output)
    times.mark("assemble")
    return {"tiles": len(tiles), "border": border, "plan": plan,
            "cache": cache.result() if cache is not None else None, "times_s": times.seconds}


def render_walk(client, rcache, scene, output, workdir, frames, camera_path, chunks, extra):
    times = _PhaseTimes()
    cache = None
    plan = render_plan(rcache, scene, extra, (frames, camera_path))
    if plan == "cache":
        chunks = max(1, min(chunks, frames))
        # Frame 0's records first, loaded by every chunk: what the chunks' views share is made once
        # (the merge drops the copies as exact duplicates) instead of once per chunk.
        base = None
        if chunks > 1:
            first = {"count": frames, "path": camera_path, "first": 0, "end": 1}
            base = client.submit(fill_task, rcache, scene, None, first, workdir, "fill_base", extra, pure=False)
        parts = []
        for c in range(chunks):
            chunk = {"count": frames, "path": camera_path, "first": frames * c // chunks,
                     "end": frames * (c + 1) // chunks}
            parts.append(client.submit(fill_task, rcache, scene, None, chunk, workdir, "fill_frames%d" % c, extra,
                                       base, pure=False))
        times.wait("fill", parts)
        cache = client.submit(merge_task, rcache, parts, os.path.join(workdir, "merged.rcc"), workdir, pure=False)
        times.wait("merge", [cache])
    stem, ext = os.path.splitext(output)
    finals = [client.submit(final_task, rcache, scene, None, {"count": frames, "path": camera_path, "index": f}, cache,
                            workdir, "final_frame%d" % f, "%s_%04d%s" % (stem, f, ext), extra, pure=False)
              for f in range(frames)]
    frame_files = client.gather(finals)
    times.mark("final")
    return {"frames": frame_files, "plan": plan, "cache": cache.result() if cache is not None else None,
            "times_s": times.seconds}


JOBQUEUE_CLUSTERS = {"slurm": "SLURMCluster", "pbs": "PBSCluster"}


def jobqueue_cluster(kind, jobs, memory, walltime, queue=None, host=None):
    """A Slurm or PBS cluster through dask-jobqueue: the scheduler runs here (the login node), each
    of `jobs` batch jobs (sbatch/qsub of a job script dask-jobqueue writes) starts one worker with one
    thread (rcache parallelises itself; one task per job keeps a job's cores for its rcache -t). The
    workers' Python is this one (sys.executable), so the cluster's nodes need the same path; files
    go through the shared --workdir as with any cluster. dask-jobqueue is not a Debian 12 package:
    `pip install dask-jobqueue` (scripts/install_dask_jobqueue.sh puts it in a venv over Debian's Dask)."""
    try:
        import dask_jobqueue
    except ImportError:
        raise RuntimeError("--cluster %s needs dask-jobqueue (pip install dask-jobqueue)" % kind)
    options = {"cores": 1, "processes": 1, "memory": memory, "walltime": walltime, "python": sys.executable}
    if queue:
        options["queue"] = queue
    if host:
        options["scheduler_options"] = {"host": host}
    cluster = getattr(dask_jobqueue, JOBQUEUE_CLUSTERS[kind])(**options)
    cluster.scale(jobs=jobs)
    return cluster


def parse_args(argv):
    extra = []
    if "--" in argv:
        i = argv.index("--")
        argv, extra = argv[:i], argv[i + 1:]
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("mode", choices=["still", "walk"])
    p.add_argument("scene")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--scheduler", help="address of a running dask scheduler (tcp://host:8786)")
    p.add_argument("--local", type=int, default=0, help="start a local cluster of N worker processes instead")
    p.add_argument("--cluster", choices=sorted(JOBQUEUE_CLUSTERS),
                   help="start the workers as batch jobs through dask-jobqueue (see jobqueue_cluster)")
    p.add_argument("--jobs", type=int, default=2, help="--cluster: batch jobs, one single-threaded worker each")
    p.add_argument("--job-memory", default="4GB", help="--cluster: memory per job (default 4GB)")
    p.add_argument("--job-walltime", default="01:00:00", help="--cluster: wall time per job")
    p.add_argument("--queue", help="--cluster: the batch queue / partition")
    p.add_argument("--scheduler-host", help="--cluster: address the scheduler listens on (default: all)")
    p.add_argument("--tiles", default="2x2", help="still: tiles across x down (default 2x2)")
    p.add_argument("--fill", choices=["independent", "checkerboard"], default="independent",
                   help="still: how tiles fill the cache (see render_still)")
    p.add_argument("--frames", type=int, default=0)
    p.add_argument("--camera-path")
    p.add_argument("--fill-chunks", type=int, default=0, help="walk: fill tasks (default: one per worker)")
    p.add_argument("--workdir", help="shared directory for parts and tiles (default: OUTPUT.dask/)")
    p.add_argument("--rcache", default=os.environ.get("RCACHE", DEFAULT_RCACHE))
    a = p.parse_args(argv)
    a.extra = extra
    return a


def main(argv):
    a = parse_args(argv)
    from dask.distributed import Client, LocalCluster
    rcache = os.path.abspath(a.rcache)
    scene = os.path.abspath(a.scene)
    output = os.path.abspath(a.output)
    workdir = os.path.abspath(a.workdir or output + ".dask")
    os.makedirs(workdir, exist_ok=True)
    defines = {}
    for i, tok in enumerate(a.extra):
        if tok == "-D" and i + 1 < len(a.extra) and "=" in a.extra[i + 1]:
            k, v = a.extra[i + 1].split("=", 1)
            defines[k] = v
    if sum(bool(x) for x in (a.local, a.cluster, a.scheduler)) > 1:
        raise SystemExit("rcache_dask: --scheduler, --local and --cluster exclude each other")
    cluster = None
    if a.local:
        cluster = LocalCluster(n_workers=a.local, threads_per_worker=1, processes=True)
    elif a.cluster:
        cluster = jobqueue_cluster(a.cluster, a.jobs, a.job_memory, a.job_walltime, a.queue, a.scheduler_host)
    client = Client(cluster if cluster else a.scheduler)
    try:
        if a.cluster:
            # Batch jobs start when the queue lets them: wait for the first worker only (tasks wait
            # for workers anyway; later jobs join the running render).
            client.wait_for_workers(1)
        client.upload_file(os.path.abspath(__file__))  # remote workers import the task functions
        workers = a.jobs if a.cluster else max(1, len(client.scheduler_info()["workers"]))
        if a.mode == "still":
            tx, ty = (int(v) for v in a.tiles.lower().split("x"))
            info = render_still(client, rcache, scene, output, workdir, tx, ty, a.extra, defines, a.fill)
        else:
            if a.frames <= 0 or not a.camera_path:
                raise SystemExit("walk: --frames N and --camera-path are required")
            info = render_walk(client, rcache, scene, output, workdir, a.frames, os.path.abspath(a.camera_path),
                               a.fill_chunks or workers, a.extra)
        print(info)
    finally:
        client.close()
        if cluster:
            cluster.close()


if __name__ == "__main__":
    try:
        main(sys.argv[1:])
    except (RuntimeError, OSError, ValueError) as e:
        # One line, as rcache itself reports: a failed rcache run names its arguments and message.
        sys.stderr.write("rcache_dask: error: %s\n" % e)
        sys.exit(1)
