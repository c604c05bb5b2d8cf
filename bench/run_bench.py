#!/usr/bin/env python3
"""Run time against error: rcache's radiance cache vs Mitsuba 3 `llvm_ad_rgb` and vs rcache's own
path tracer, side by side in one interleaved run.

For each bench scene: a ground-truth reference rendered by Mitsuba 3 at high spp (independent
sampler; cached by a hash of the scene's files and settings; rcache's path tracer only when no Mitsuba
is found or with --no-mitsuba), then three curves whose jobs alternate: Mitsuba `llvm_ad_rgb` at an
spp ladder (bench/mitsuba_render.py: one Python process per image, the scene file as is), rcache's
path tracer at an spp ladder, and rcache at a ladder of settings. Every point is the wall time of
the whole process as a user runs it, and its relMSE against the reference, as one JSON line.
Dr.Jit compiles a kernel per (scene, res, spp) and caches it on disk: every Mitsuba point is
rendered once untimed right before its timed run (JIT warm-up; the cold time is kept as
time_cold_s). From the curves: the time each method needs to reach given relMSE levels, the ratios
Mitsuba/rcache and path/rcache (summary.md), a log-log plot per scene, an image strip at equal time.
Usage:  bench/run_bench.py [--quick] [--out DIR] [--scenes a,b] [--threads N] [--no-mitsuba]
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
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RCACHE = os.path.join(ROOT, "build", "rcache")

# Scenes and the ladders. Full mode: 512×512 as the issue asks; quick mode: small images, short ladders.
# rcache ladder entries: cache settings (empty = the integrator's defaults) and pixel samples. Both
# matter: the cache settings set the interpolation error, spp the noise of direct light, edges
# and the materials rcache path traces (too sharp for the cache).
SCENES = ["cornell_glossy", "glossy_sweep", "aniso_sphere", "curved_glossy", "cornell_diffuse",
          "envmap_product", "envmap_evening", "corridor"]
# Quick mode's default: one box, one envmap scene, the corridor.
QUICK_SCENES = ["cornell_glossy", "envmap_product", "corridor"]
# Adaptive sampling (--adaptive T, --max-spp N) is offered to both methods with the same thresholds;
# each method's curve is the best error it reaches by each time over all its settings.
# Mitsuba's ladder is in powers of 4 from 4: its ldsampler rounds any other count (1 too) up to one.
FULL = dict(res=512, ref_spp=4096, path_spp=[4, 8, 16, 32, 64, 128, 256], mitsuba_spp=[4, 16, 64, 256, 1024],
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
                      ("env_cache=false", {"env_cache": "false"}), ("fallback=false", {"fallback": "false"}),
                      ("frame=world", {"frame": "world"}), ("mode=tl", {"mode": "tl"})],
            variant_spp=16)
QUICK = dict(res=96, ref_spp=1024, path_spp=[1, 4, 16, 64], mitsuba_spp=[4, 16, 64, 256],
             path_adaptive=[(dict(adapt=0.05), 16)],
             rcache=[(dict(), 2), (dict(), 8), (dict(), 32), (dict(rays=256, a=0.5), 8), (dict(rays=256, a=0.5), 32),
                     (dict(rays=1024, a=0.3), 32), (dict(adapt=0.05), 8)],
             variants=[("adaptive=true", {"adaptive": "true"}), ("frame=world", {"frame": "world"}),
                       ("env_cache=false", {"env_cache": "false"}), ("fallback=false", {"fallback": "false"}),
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
    wall, mem, code, err = timed_process(cmd)
    if code != 0:
        raise RuntimeError("render failed (%d): %s\n%s" % (code, " ".join(cmd), err.strip()))
    with open(stats_path) as f:
        stats = json.load(f)
    return wall, mem, stats


def timed_process(cmd):
    """Wall time, peak memory (MiB; wait4 gives this child's own rusage), exit code and stderr of cmd."""
    with tempfile.TemporaryFile(mode="w+") as err:
        t0 = time.perf_counter()
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=err, text=True)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - t0
        err.seek(0)
        return wall, usage.ru_maxrss / 1024.0, os.waitstatus_to_exitcode(status), err.read()


MITSUBA_RENDER = os.path.join(ROOT, "bench", "mitsuba_render.py")
MITSUBA_VARIANT = "llvm_ad_rgb"
DEFAULT_VENV = os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "rcache", "bench-venv")


def find_mitsuba_python():
    """A Python whose mitsuba runs llvm_ad_rgb: $RCACHE_MITSUBA_PYTHON, this one, the bench venv."""
    candidates = [os.environ.get("RCACHE_MITSUBA_PYTHON"), sys.executable, os.path.join(DEFAULT_VENV, "bin", "python")]
    for exe in candidates:
        if exe and os.path.exists(exe) and subprocess.run(
                [exe, "-c", "import mitsuba; mitsuba.set_variant('%s')" % MITSUBA_VARIANT],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0:
            return exe
    return None


def mitsuba_version(python):
    out = subprocess.run([python, "-c", "import mitsuba, drjit; print(mitsuba.__version__, drjit.__version__)"],
                         capture_output=True, text=True)
    return out.stdout.strip()


def render_mitsuba(python, scene_path, out_exr, spp, res, threads, seed=0, sampler=None):
    """Wall time of one whole Mitsuba process (interpreter, import, load, JIT, render, write)."""
    cmd = [python, MITSUBA_RENDER, scene_path, out_exr, str(res), str(spp), str(seed), str(threads), MITSUBA_VARIANT]
    if sampler:
        cmd.append(sampler)
    if shutil.which("taskset"):
        cmd = ["taskset", "-c", "0-%d" % (threads - 1)] + cmd
    wall, mem, code, err = timed_process(cmd)
    if code != 0:
        raise RuntimeError("mitsuba failed on %s: %s" % (scene_path, err.strip()[-500:]))
    return wall, mem


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
            if name.endswith((".xml", ".obj", ".ply", ".exr")):
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
    ap.add_argument("--quick", action="store_true", help="small images, short ladders, three scenes")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "out"))
    ap.add_argument("--scenes", default=None, help="comma-separated scene names (default: all bench scenes)")
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--no-plot", action="store_true")
    ap.add_argument("--no-mitsuba", action="store_true", help="no Mitsuba 3 curve; rcache's path tracer renders the reference")
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
    scenes = args.scenes.split(",") if args.scenes else (QUICK_SCENES if args.quick else SCENES)
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
    versions = dict(mitsuba=mitsuba_version(mitsuba_python) if mitsuba_python else None)
    print("bench: Mitsuba 3 %s curve: %s" % (MITSUBA_VARIANT, mitsuba_python or "off (no Python with mitsuba found)"),
          file=sys.stderr)
    with open(jsonl_path, "w") as jsonl:
        def emit(rec):
            rec.update(machine=machine, date=time.strftime("%Y-%m-%d"), quick=args.quick, res=cfg["res"])
            jsonl.write(json.dumps(rec) + "\n")
            jsonl.flush()
            print(json.dumps(rec), flush=True)

        for name in scenes:
            scene_path = os.path.join(ROOT, "scenes", name + ".xml")
            work = os.path.join(args.out, name)
            os.makedirs(work, exist_ok=True)
            ref_by = ("mitsuba %s independent" % versions["mitsuba"]) if mitsuba_python else "rcache path"
            key = scene_hash(scene_path, dict(res=cfg["res"], spp=cfg["ref_spp"], seed=REFERENCE_SEED, by=ref_by))
            ref = os.path.join(args.out, "ref", "%s-%s.exr" % (name, key))
            if not os.path.exists(ref):
                print("bench: rendering reference for %s (%s, %d spp)" % (name, ref_by, cfg["ref_spp"]),
                      file=sys.stderr, flush=True)
                tmp = ref + ".tmp.exr"
                if mitsuba_python:
                    wall, _ = render_mitsuba(mitsuba_python, scene_path, tmp, cfg["ref_spp"], cfg["res"], args.threads,
                                             seed=REFERENCE_SEED, sampler="independent")
                else:
                    wall, _, _ = render(scene_path, tmp, "path", cfg["ref_spp"], cfg["res"], args.threads, {},
                                        os.path.join(work, "ref_stats.json"), seed=REFERENCE_SEED)
                os.replace(tmp, ref)
                emit(dict(scene=name, method="reference", by=ref_by, spp=cfg["ref_spp"], time_s=wall))
            points = {"path": [], "rcache": [], "mitsuba": []}
            # Jobs of the three methods, run alternately: this VM's speed drifts by up to 30 % over
            # minutes (and other work shares it), and interleaving spreads a slow spell over every curve.
            mitsuba_jobs = [("mitsuba", "%s spp=%d" % (MITSUBA_VARIANT, n), "mitsuba_%d" % n, n, {})
                            for n in (cfg["mitsuba_spp"] if mitsuba_python else [])]
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
            for k in range(max(len(path_jobs), len(rcache_jobs), len(mitsuba_jobs))):
                jobs += mitsuba_jobs[k:k + 1] + path_jobs[k:k + 1] + rcache_jobs[k:k + 1]
            for method, label, tag, spp, settings in jobs:
                out = os.path.join(work, tag + ".exr")
                if method == "mitsuba":
                    # The JIT warm-up: the same render once, untimed (another seed), fills Dr.Jit's
                    # kernel cache for this (scene, res, spp); the timed run then finds it there.
                    cold, _ = render_mitsuba(mitsuba_python, scene_path, out, spp, cfg["res"], args.threads, seed=1)
                    wall, mem = render_mitsuba(mitsuba_python, scene_path, out, spp, cfg["res"], args.threads, seed=0)
                    err = diff(out, ref)
                    p = dict(scene=name, method=method, setting=label, spp=spp, time_s=wall, time_cold_s=cold,
                             relmse=err["relmse"], rmse=err["rmse"], peak_mib=mem, image=out,
                             mitsuba_version=versions["mitsuba"])
                    points[method].append(p)
                    emit(dict(p))
                    continue
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
            # Time to reach the errors that every curve spans (the worst of the best errors, ×1, ×2, ×4),
            # plus rcache's own best error against Mitsuba's curve when Mitsuba reaches it.
            curves = [m for m in ("rcache", "path", "mitsuba") if points[m]]
            floor = max(min(p["relmse"] for p in points[m]) for m in curves)
            targets = sorted({floor * f for f in (1.0, 2.0, 4.0)})
            for target in targets:
                t = {m: time_to_reach(points[m], target) for m in curves}
                rec = dict(scene=name, method="time_to_error", relmse_target=target, reference=ref_by,
                           rcache_s=t.get("rcache"), path_s=t.get("path"), mitsuba_s=t.get("mitsuba"),
                           speedup_path_over_rcache=(t["path"] / t["rcache"]) if t.get("path") and t.get("rcache") else None,
                           speedup_mitsuba_over_rcache=(t["mitsuba"] / t["rcache"])
                           if t.get("mitsuba") and t.get("rcache") else None)
                emit(rec)
                summary.append(rec)
            if not args.no_plot:
                plot_scene(name, points, os.path.join(args.out, "%s_error_vs_time.png" % name))
                strip(name, points, ref, work, os.path.join(args.out, "%s_strip.png" % name))
    write_summary(os.path.join(args.out, "summary.md"), summary, machine, versions, args, cfg)
    print("bench: wrote %s" % jsonl_path, file=sys.stderr)


def write_summary(path, summary, machine, versions, args, cfg):
    """The ratios as a Markdown table: time to equal relMSE, Mitsuba LLVM / rcache and path / rcache."""
    def fmt(x, spec):
        return "—" if x is None else spec % x
    lines = ["# bench/run_bench.py %s, %s" % ("--quick" if args.quick else "(full)", time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())),
             "", "%s; %d² px; reference: %s at %d spp; Mitsuba %s (%s), one Python process per image, JIT warm"
             % (machine, cfg["res"], summary[0]["reference"] if summary else "?", cfg["ref_spp"], versions["mitsuba"] or "absent",
                MITSUBA_VARIANT), "",
             "| scene | relMSE | Mitsuba s | path s | rcache s | **Mitsuba / rcache** | path / rcache |",
             "|---|---|---|---|---|---|---|"]
    for r in summary:
        lines.append("| %s | %.2e | %s | %s | %s | **%s** | %s |" % (
            r["scene"], r["relmse_target"], fmt(r["mitsuba_s"], "%.2f"), fmt(r["path_s"], "%.2f"), fmt(r["rcache_s"], "%.2f"),
            fmt(r["speedup_mitsuba_over_rcache"], "%.2f×"), fmt(r["speedup_path_over_rcache"], "%.2f×")))
    lines.append("")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    print("bench: wrote %s" % path, file=sys.stderr)


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
        label = {"mitsuba": "Mitsuba 3 " + MITSUBA_VARIANT, "path": "rcache path tracer", "rcache": "rcache radiance cache"}[method]
        ax.loglog([t for t, _ in front], [e for _, e in front], style + "-", color=colour, label=label)
    ax.set_xlabel("wall time of the whole process (s)")
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
