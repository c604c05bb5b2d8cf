#!/usr/bin/env python3
"""Run time against error: rcache's radiance cache vs its path tracer, side by side in one run.

For each bench scene: a path-traced reference (cached by a hash of the scene's files and settings),
then a ladder of path-tracer spp and a ladder of rcache settings. Every point records wall time,
relMSE, RMSE, records and peak memory as one JSON line. From the curves: the time each method needs
to reach given relMSE levels, and the ratio path/rcache; a log-log plot per scene; an image strip at
equal time. Usage:  bench/run_bench.py [--quick] [--out DIR] [--scenes a,b] [--threads N]
"""
import argparse
import hashlib
import json
import math
import os
import platform
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RCACHE = os.path.join(ROOT, "build", "rcache")

# Scenes and the ladders. Full mode: 512×512 as the issue asks; quick mode: small images, short ladders.
# rcache ladder entries: cache settings (empty = the integrator's defaults) and pixel samples. Both
# matter: the cache settings set the interpolation error, spp the noise of direct light, edges
# and the materials rcache path traces (too sharp for the cache).
SCENES = ["cornell_glossy", "glossy_sweep", "aniso_sphere", "curved_glossy", "cornell_diffuse"]
# Adaptive sampling (--adaptive T, --max-spp N) is offered to both methods with the same thresholds;
# each method's curve is the best error it reaches by each time over all its settings.
FULL = dict(res=512, ref_spp=4096, path_spp=[4, 8, 16, 32, 64, 128, 256],
            path_adaptive=[(dict(adapt=0.05), 16), (dict(adapt=0.05), 32), (dict(adapt=0.02), 32)],
            rcache=[(dict(), 4), (dict(), 8), (dict(), 16), (dict(), 32), (dict(), 64), (dict(), 128), (dict(), 256),
                    (dict(rays=256, a=0.5), 16),
                    (dict(rays=256, a=0.5), 64), (dict(rays=1024, a=0.3), 64),
                    (dict(adapt=0.05), 16), (dict(adapt=0.05), 32), (dict(adapt=0.02), 32),
                    (dict(adapt=0.02), 64), (dict(adapt=0.02, rays=1024, a=0.3), 64),
                    # cheaper caches for the small budgets (the fill is most of the time there)
                    (dict(rays=128, a=0.6), 16), (dict(adapt=0.05, rays=128, a=0.6), 16),
                    (dict(adapt=0.05, rays=256, a=0.5), 16)],
            variants=[("adaptive=true", {"adaptive": "true"}), ("gradients=false", {"gradients": "false"}),
                      ("frame=world", {"frame": "world"}), ("mode=tl", {"mode": "tl"})],
            variant_spp=16)
QUICK = dict(res=96, ref_spp=512, path_spp=[1, 4, 16, 64],
             path_adaptive=[(dict(adapt=0.05), 16)],
             rcache=[(dict(), 2), (dict(), 8), (dict(), 32), (dict(rays=256, a=0.5), 8), (dict(rays=256, a=0.5), 32),
                     (dict(rays=1024, a=0.3), 32), (dict(adapt=0.05), 8)],
             variants=[("adaptive=true", {"adaptive": "true"}), ("frame=world", {"frame": "world"}),
                       ("mode=tl", {"mode": "tl"})],
             variant_spp=8)


# The reference's seed. Pixel sample s of every render draws from a stream fixed by (seed, pixel, s),
# so with a shared seed the first N samples of the reference would be the very samples of an N-spp
# test image: their error against it would be understated by up to (1 - N/ref_spp)^2 and the
# reference's own noise would cancel. A seed no test render uses keeps them independent.
REFERENCE_SEED = 7919


# Ladder settings that are command-line flags rather than -D parameters.
CLI_SETTINGS = {"adapt": "--adaptive", "max_spp": "--max-spp"}  # "adaptive" is the -D of adaptive caching


def render(scene_path, out_exr, integrator, spp, res, threads, defines, stats_path, seed=0):
    cmd = [RCACHE, scene_path, "-o", out_exr, "--integrator", integrator, "--spp", str(spp), "--quiet",
           "--stats", stats_path, "-t", str(threads), "-D", "res=%d" % res, "--seed", str(seed)]
    for k, v in defines.items():
        cmd += [CLI_SETTINGS[k], str(v)] if k in CLI_SETTINGS else ["-D", "%s=%s" % (k, v)]
    # Peak memory of this child alone: wait4 returns its own rusage.
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    err = proc.stderr.read()
    proc.stdout.read()
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        raise RuntimeError("render failed (%d): %s\n%s" % (code, " ".join(cmd), err.strip()))
    with open(stats_path) as f:
        stats = json.load(f)
    return wall, usage.ru_maxrss / 1024.0, stats


# Mitsuba 3 as one more curve when some Python on this machine has it (never required). The child
# process loads the scene with the same $res/$spp and times load + render (the interpreter start
# and the mitsuba import are not counted: they are not part of rendering).
MITSUBA_RENDER = r"""
import sys, time
t0 = time.perf_counter()
import mitsuba as mi
mi.set_variant("scalar_rgb")
t1 = time.perf_counter()
scene = mi.load_file(sys.argv[1], res=int(sys.argv[3]), spp=int(sys.argv[4]))
img = mi.render(scene, spp=int(sys.argv[4]))
t2 = time.perf_counter()
mi.Bitmap(img).write(sys.argv[2])
print(t2 - t1)
"""


def find_mitsuba_python():
    for exe in [shutil.which("python3"), "/usr/bin/python3", sys.executable]:
        if exe and subprocess.run([exe, "-c", "import mitsuba; mitsuba.set_variant('scalar_rgb')"],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0:
            return exe
    return None


def render_mitsuba(python, scene_path, out_exr, spp, res, threads):
    cmd = ["taskset", "-c", "0-%d" % (threads - 1), python, "-c", MITSUBA_RENDER, scene_path, out_exr, str(res), str(spp)]
    if not shutil.which("taskset"):
        cmd = cmd[3:]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        print("bench: mitsuba failed on %s: %s" % (scene_path, proc.stderr.strip()[-300:]), file=sys.stderr)
        return None
    return float(proc.stdout.strip().splitlines()[-1])


def diff(test, ref, heatmap=None):
    cmd = [RCACHE, "diff", test, ref, "--json"]
    if heatmap:
        cmd += ["--heatmap", heatmap]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def scene_hash(scene_path, settings):
    h = hashlib.sha256()
    base = os.path.dirname(scene_path)
    for dirpath, _, files in os.walk(base):
        for name in sorted(files):
            if name.endswith((".xml", ".obj", ".ply")):
                with open(os.path.join(dirpath, name), "rb") as f:
                    h.update(name.encode())
                    h.update(f.read())
    h.update(json.dumps(settings, sort_keys=True).encode())
    return h.hexdigest()[:16]


def label_of(settings, spp):
    parts = ["%s=%s" % (k, settings[k]) for k in sorted(settings)] or ["defaults"]
    return ",".join(parts + ["spp=%d" % spp])


def time_to_reach(points, target):
    """Time at which the best-so-far front (the lowest relMSE reached by each time, over all
    settings) falls to target, log-log interpolated between front points; None if never reached."""
    front, best = [], float("inf")
    for t, e in sorted((p["time_s"], p["relmse"]) for p in points if p["relmse"] > 0):
        if e < best:
            front.append((t, e))
            best = e
    if not front or front[-1][1] > target:
        return None
    if front[0][1] <= target:
        return front[0][0]
    for (t0, e0), (t1, e1) in zip(front, front[1:]):
        if e1 <= target < e0:
            f = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="small images, short ladders (< 5 min on 2 cores)")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "out"))
    ap.add_argument("--scenes", default=None, help="comma-separated scene names (default: all bench scenes)")
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--no-plot", action="store_true")
    ap.add_argument("--no-mitsuba", action="store_true", help="skip the Mitsuba 3 curve even if mitsuba is installed")
    ap.add_argument("--res", type=int, default=None, help="override the image size of the chosen mode")
    ap.add_argument("--ref-spp", type=int, default=None, help="override the reference spp of the chosen mode")
    ap.add_argument("--no-variants", action="store_true", help="only the ladders (skip adaptive/gradient/frame/tl variants)")
    ap.add_argument("--replot", action="store_true", help="redraw the error-vs-time plots from OUT/results.jsonl")
    args = ap.parse_args()
    if args.replot:
        by_scene = {}
        with open(os.path.join(args.out, "results.jsonl")) as f:
            for line in f:
                p = json.loads(line)
                pts = by_scene.setdefault(p["scene"], {"path": [], "rcache": [], "mitsuba": []})
                if p["method"] in ("path", "mitsuba") or (p["method"] == "rcache" and p.get("ladder")):
                    pts[p["method"]].append(p)
        for name, pts in by_scene.items():
            plot_scene(name, pts, os.path.join(args.out, "%s_error_vs_time.png" % name))
        return
    cfg = dict(QUICK if args.quick else FULL)
    if args.res:
        cfg["res"] = args.res
    if args.ref_spp:
        cfg["ref_spp"] = args.ref_spp
    scenes = args.scenes.split(",") if args.scenes else (SCENES[:2] if args.quick else SCENES)
    if not os.path.exists(RCACHE):
        sys.exit("bench: %s not found; run scripts/build.sh first" % RCACHE)
    os.makedirs(args.out, exist_ok=True)
    os.makedirs(os.path.join(args.out, "ref"), exist_ok=True)
    jsonl_path = os.path.join(args.out, "results.jsonl")
    if os.path.exists(jsonl_path):  # keep the previous run's lines next to the new ones' file
        os.replace(jsonl_path, jsonl_path + ".prev")
    machine = "%s, %d threads" % (platform.processor() or platform.machine(), args.threads)
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    machine = "%s, %d threads" % (line.split(":", 1)[1].strip(), args.threads)
                    break
    except OSError:
        pass
    summary = []
    mitsuba_python = None if args.no_mitsuba else find_mitsuba_python()
    print("bench: Mitsuba 3 curve: %s" % (mitsuba_python or "off (no Python with mitsuba found)"), file=sys.stderr)
    with open(jsonl_path, "w") as jsonl:
        def emit(rec):
            rec.update(machine=machine, date=time.strftime("%Y-%m-%d"), quick=args.quick)
            jsonl.write(json.dumps(rec) + "\n")
            jsonl.flush()
            print(json.dumps(rec), flush=True)

        for name in scenes:
            scene_path = os.path.join(ROOT, "scenes", name + ".xml")
            work = os.path.join(args.out, name)
            os.makedirs(work, exist_ok=True)
            key = scene_hash(scene_path, dict(res=cfg["res"], spp=cfg["ref_spp"], seed=REFERENCE_SEED))
            ref = os.path.join(args.out, "ref", "%s-%s.exr" % (name, key))
            if not os.path.exists(ref):
                print("bench: rendering reference for %s (%d spp)" % (name, cfg["ref_spp"]), file=sys.stderr, flush=True)
                wall, _, _ = render(scene_path, ref, "path", cfg["ref_spp"], cfg["res"], args.threads, {},
                                    os.path.join(work, "ref_stats.json"), seed=REFERENCE_SEED)
                emit(dict(scene=name, method="reference", spp=cfg["ref_spp"], time_s=wall))
            points = {"path": [], "rcache": [], "mitsuba": []}
            if mitsuba_python:
                for spp in cfg["path_spp"]:
                    out = os.path.join(work, "mitsuba_%d.exr" % spp)
                    t = render_mitsuba(mitsuba_python, scene_path, out, spp, cfg["res"], args.threads)
                    if t is None:
                        break
                    err = diff(out, ref)
                    p = dict(scene=name, method="mitsuba", setting="scalar_rgb spp=%d" % spp, spp=spp, time_s=t,
                             relmse=err["relmse"], rmse=err["rmse"], image=out)
                    points["mitsuba"].append(p)
                    emit(dict(p))
            # Jobs of both methods, run alternately: this VM's speed drifts by up to 30 % over minutes,
            # and interleaving spreads a slow spell over both curves instead of one.
            path_jobs = [("path", "spp=%d" % n, "path_%d" % n, n, {}) for n in cfg["path_spp"]]
            for st, n in cfg["path_adaptive"]:
                label = label_of(st, n)
                path_jobs.append(("path", label, "path_" + label.replace("=", "").replace(",", "_"), n, st))
            ladder = [(label_of(st, n), st, n) for st, n in cfg["rcache"]]
            variants = [] if args.no_variants else [
                ("%s,spp=%d" % (vlabel, cfg["variant_spp"]), vdef, cfg["variant_spp"]) for vlabel, vdef in cfg["variants"]]
            ladder_labels = {label for label, _, _ in ladder}
            rcache_jobs = [("rcache", label, "rcache_" + label.replace("=", "").replace(",", "_"), n, st)
                           for label, st, n in ladder + variants]
            jobs = []
            for k in range(max(len(path_jobs), len(rcache_jobs))):
                jobs += path_jobs[k:k + 1] + rcache_jobs[k:k + 1]
            for method, label, tag, spp, settings in jobs:
                out = os.path.join(work, tag + ".exr")
                wall, mem, stats = render(scene_path, out, method, spp, cfg["res"], args.threads,
                                          {k: str(v) for k, v in settings.items()}, os.path.join(work, tag + ".json"))
                err = diff(out, ref)
                p = dict(scene=name, method=method, setting=label, spp=spp, time_s=wall, relmse=err["relmse"],
                         rmse=err["rmse"], peak_mib=mem, records=stats.get("records", 0), image=out,
                         spp_mean=stats.get("samples_per_pixel_mean"))
                if method == "rcache":
                    p["ladder"] = label in ladder_labels
                if method == "path" or p["ladder"]:
                    points[method].append(p)
                emit(dict(p))
            # Time to reach the errors that both curves span.
            best_rc = min(p["relmse"] for p in points["rcache"])
            best_pt = min(p["relmse"] for p in points["path"])
            targets = sorted({max(best_rc, best_pt) * f for f in (1.0, 2.0, 4.0)})
            for target in targets:
                t_rc = time_to_reach(points["rcache"], target)
                t_pt = time_to_reach(points["path"], target)
                ratio = (t_pt / t_rc) if (t_rc and t_pt) else None
                rec = dict(scene=name, method="time_to_error", relmse_target=target, rcache_s=t_rc, path_s=t_pt,
                           speedup_path_over_rcache=ratio)
                emit(rec)
                summary.append(rec)
            if not args.no_plot:
                plot_scene(name, points, os.path.join(args.out, "%s_error_vs_time.png" % name))
                strip(name, points, ref, work, os.path.join(args.out, "%s_strip.png" % name))
    print("bench: wrote %s" % jsonl_path, file=sys.stderr)


def plot_scene(name, points, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("bench: matplotlib missing (apt-get install python3-matplotlib); no plot", file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(5, 4), dpi=120)
    for method, style, colour in (("path", "o", "C0"), ("rcache", "s", "C1"), ("mitsuba", "^", "C2")):
        pts = sorted((p["time_s"], p["relmse"]) for p in points.get(method, []))
        if not pts:
            continue
        # Every measured point, and a line through the best error reached by each time (the
        # settings one would pick at that budget): the ladder mixes rays, a and spp.
        front, best = [], float("inf")
        for t, e in pts:
            if e < best:
                front.append((t, e))
                best = e
        ax.loglog([t for t, _ in pts], [e for _, e in pts], style, color=colour, alpha=0.5)
        label = "mitsuba scalar_rgb (load+render only)" if method == "mitsuba" else method + " (process wall time)"
        ax.loglog([t for t, _ in front], [e for _, e in front], style + "-", color=colour, label=label)
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("relMSE vs reference")
    ax.set_title(name)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def strip(name, points, ref, work, path):
    """Path tracer and rcache at (about) equal time, the reference, and their error heat maps."""
    rc = points["rcache"][len(points["rcache"]) // 2] if points["rcache"] else None
    if not rc or not points["path"]:
        return
    pt = min(points["path"], key=lambda p: abs(math.log(p["time_s"] / rc["time_s"])))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.image as mpimg
    except ImportError:
        return
    tiles = []
    for label, img in (("path %.1fs" % pt["time_s"], pt["image"]), ("rcache %.1fs" % rc["time_s"], rc["image"]),
                       ("reference", ref)):
        png = os.path.join(work, os.path.basename(img).replace(".exr", ".png"))
        subprocess.run([RCACHE, "diff", img, ref, "--json", "--heatmap", png + ".heat.png"], check=True,
                       capture_output=True)
        convert_png(img, png)
        tiles.append((label, png, png + ".heat.png" if img != ref else None))
    fig, axes = plt.subplots(2, 3, figsize=(9, 6), dpi=100)
    for col, (label, png, heat) in enumerate(tiles):
        axes[0][col].imshow(mpimg.imread(png))
        axes[0][col].set_title(label)
        if heat:
            axes[1][col].imshow(mpimg.imread(heat))
            axes[1][col].set_title("rel. error")
        for r in range(2):
            axes[r][col].axis("off")
    fig.suptitle("%s at equal time" % name)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def convert_png(exr, png):
    """EXR → PNG via OpenImageIO's oiiotool when present (sRGB), else skipped."""
    tool = shutil.which("oiiotool")
    if tool:
        subprocess.run([tool, exr, "--colorconvert", "linear", "sRGB", "-o", png], check=False, capture_output=True)


if __name__ == "__main__":
    main()
