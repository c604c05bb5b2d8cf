#!/usr/bin/env python3
"""Per-sample cost of rcache's path tracer (and rcache's final pass) against Mitsuba 3 `llvm_ad_rgb`.

Whole processes are timed, interleaved (every repetition runs each renderer once per scene, in
turn), so that load from other processes on the machine hits all of them alike; compare the
ratios, not the absolute times. The per-sample cost is the slope between two sample counts:
    ms/spp = (t(spp_hi) - t(spp_lo)) / (spp_hi - spp_lo)    (minimum over repetitions of each t)
which cancels every fixed cost (interpreter start, import, scene load, BVH build, Dr.Jit's kernel
compile — whose cache is warmed once per configuration before timing — image write). Two clocks:
wall time, and the CPU time of the process (all its threads, from wait4). On a machine shared with
other work the CPU time is the steadier measure of the work per sample; on a quiet machine with
threads that scale the two agree up to the thread count.

Renderers (each a whole process, same scene file, same -D res, same thread count):
  mitsuba      Mitsuba 3 llvm_ad_rgb, the file's own integrator (path), mi.render(scene, spp=N)
  path         rcache --integrator path
  path_ref     (with --rcache-ref) another rcache build's path tracer, e.g. main before this change
  rcache_final (with --final) rcache --integrator rcache: the final pass's slope (with
               -D follow_budget=false the fill is the same at both sample counts, so it cancels)

With --no-mitsuba only the rcache builds run (an A/B of `path` against `path_ref`).

Usage (repository root, after scripts/build.sh):
  /root/.cache/rcache/bench-venv/bin/python bench/per_sample.py --res 256 --threads 2 \
      [--spp 16 80] [--reps 3] [--scenes cornell_glossy furnace] [--rcache-ref /work/main/build/rcache] [--final]
Needs DRJIT_LIBLLVM_PATH (defaults to Debian 12's libLLVM-19 when unset). Prints a Markdown table.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

SCENES = ["cornell_glossy", "cornell_diffuse", "glossy_sweep", "aniso_sphere", "curved_glossy", "furnace"]

MITSUBA = r"""
import sys
import drjit as dr
import mitsuba as mi
mi.set_variant("llvm_ad_rgb")
dr.set_thread_count(int(sys.argv[5]))
scene = mi.load_file(sys.argv[1], res=int(sys.argv[3]), spp=int(sys.argv[4]))
img = mi.render(scene, spp=int(sys.argv[4]))
mi.Bitmap(img).write(sys.argv[2])
"""


def timed(cmd, env=None):
    """(wall seconds, CPU seconds of the process and all its threads)."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        raise RuntimeError("failed (%d): %s\n%s" % (code, " ".join(cmd), err.strip()[-500:]))
    return wall, usage.ru_utime + usage.ru_stime


def pin(cmd, threads):
    return (["taskset", "-c", "0-%d" % (threads - 1)] if shutil.which("taskset") else []) + cmd


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rcache", default="build/rcache")
    ap.add_argument("--rcache-ref", default=None)
    ap.add_argument("--final", action="store_true")
    ap.add_argument("--res", type=int, default=256)
    ap.add_argument("--spp", type=int, nargs=2, default=[16, 80])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--scenes", nargs="*", default=SCENES)
    ap.add_argument("--python", default=sys.executable, help="a Python with mitsuba")
    ap.add_argument("--no-mitsuba", action="store_true", help="rcache builds only (an A/B of two builds)")
    args = ap.parse_args()
    env = dict(os.environ)
    env.setdefault("DRJIT_LIBLLVM_PATH", "/usr/lib/x86_64-linux-gnu/libLLVM-19.so")
    work = tempfile.mkdtemp(prefix="rcache_per_sample_")
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

    def commands(scene, spp):
        path = os.path.join(root, "scenes", scene + ".xml")
        out = os.path.join(work, scene)
        rc = lambda exe, integ: pin([exe, path, "--integrator", integ, "--spp", str(spp), "-D", "res=%d" % args.res,
                                     "-t", str(args.threads), "--quiet", "-o", out + "_%s.exr" % integ], args.threads)
        cmds = {} if args.no_mitsuba else {
            "mitsuba": pin([args.python, "-c", MITSUBA, path, out + "_mi.exr", str(args.res), str(spp), str(args.threads)],
                           args.threads)}
        cmds["path"] = rc(args.rcache, "path")
        if args.rcache_ref:
            cmds["path_ref"] = rc(args.rcache_ref, "path")
        if args.final:
            # Records at their base settings at both sample counts (follow_budget=false), so the fill
            # is the same and cancels in the slope.
            cmds["rcache_final"] = rc(args.rcache, "rcache") + ["-D", "follow_budget=false"]
        return cmds

    names = list(commands(args.scenes[0], 1).keys())
    best = {}
    for scene in args.scenes if not args.no_mitsuba else []:
        for spp in args.spp:  # warm Dr.Jit's kernel cache (and the page cache) for every configuration
            timed(commands(scene, spp)["mitsuba"], env)
    for rep in range(args.reps):
        for scene in args.scenes:
            for spp in args.spp:
                for name, cmd in commands(scene, spp).items():
                    for clock, t in zip(("wall", "cpu"), timed(cmd, env)):
                        key = (clock, scene, spp, name)
                        best[key] = min(best.get(key, t), t)
    lo, hi = args.spp
    for clock in ("cpu", "wall"):
        print("\n%s time:\n" % clock)
        peer = not args.no_mitsuba
        print("| scene | " + " | ".join("%s ms/spp" % n for n in names) + " |" + (" path / mitsuba |" if peer else "") +
              (" path_ref / path |" if args.rcache_ref else "") + (" final / mitsuba |" if args.final and peer else ""))
        print("|---" * (len(names) + 1 + peer + bool(args.rcache_ref) + bool(args.final and peer)) + "|")
        for scene in args.scenes:
            slope = {n: 1000.0 * (best[(clock, scene, hi, n)] - best[(clock, scene, lo, n)]) / (hi - lo) for n in names}
            row = "| %s | " % scene + " | ".join("%.2f" % slope[n] for n in names) + " |"
            if peer:
                row += " %.2f |" % (slope["path"] / slope["mitsuba"])
            if args.rcache_ref:
                row += " %.3f |" % (slope["path_ref"] / slope["path"])
            if args.final and peer:
                row += " %.2f |" % (slope["rcache_final"] / slope["mitsuba"])
            print(row, flush=True)


if __name__ == "__main__":
    main()
