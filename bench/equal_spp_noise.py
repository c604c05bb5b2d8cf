#!/usr/bin/env python3
"""Noise at equal samples per pixel: rcache's path tracer against Mitsuba 3 (a measurement script).

Time to equal error = (time per sample) × (variance per sample). bench/per_sample.py measures the
first factor; this script measures the second, which no machine load moves: several independent
renders (seeds) per renderer at the same spp, against one common high-spp reference.

  export DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so
  nice -n 19 /root/.cache/rcache/bench-venv/bin/python bench/equal_spp_noise.py --res 128 --spp 64 \
      --seeds 8 --spp-ref 4096 [--scenes envmap_product corridor] [-D max_depth=2] \
      [--rcache old=/path/to/old/rcache --rcache new=build/rcache] [--integrator rcache] [--json-out FILE]

Per scene (the file as is, plus -D; both renderers use the file's sampler, or --sampler, and the file's
reconstruction filter):
  ref       Mitsuba (--variant) at --spp-ref with the `independent` sampler, seed 0 (kept in --outdir
            and reused by later runs with the same scene, res, -D and spp-ref);
  mitsuba   Mitsuba at --spp, seeds 1 … --seeds (kept and reused too);
  LABEL     each --rcache build, `--integrator path` (or --integrator) at --spp, seeds 1 … --seeds.
Figures per renderer:
  relmse    relMSE against ref, averaged over the seeds (bench/mitsuba_crosscheck.py's definition)
  relvar    the same normalisation applied to the per-pixel variance across the seeds
            (mean over pixels and channels of s² / (r² + 0.01)): the variance per pixel at --spp,
            free of the reference's own noise and of any bias
  mean      mean of all seeds' images / mean of ref, per channel (a bias check)
and the ratios relvar / Mitsuba's relvar and relmse / Mitsuba's relmse.
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mitsuba_crosscheck import mitsuba_scene_copy, relmse  # noqa: E402  (one definition of each)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def tag(name, args, extra):
    defines = "".join("_%s%s" % kv for kv in sorted(extra.items()))
    return "%s_r%d%s" % (name, args.res, defines)


def mitsuba_image(mi, scene_path, sampler, spp, seed, out, args, extra):
    if not os.path.exists(out):
        load_path = scene_path if sampler is None else mitsuba_scene_copy(scene_path, sampler)
        try:
            scene = mi.load_file(load_path, **{"res": args.res, "spp": spp, **extra})
        finally:
            if load_path != scene_path:
                os.remove(load_path)
        mi.Bitmap(mi.render(scene, spp=spp, seed=seed)).write(out)
    return np.array(mi.Bitmap(out), dtype=np.float64)[..., :3]


def rcache_image(mi, binary, scene_path, seed, out, args, extra):
    cmd = [binary, scene_path, "-o", out, "--integrator", args.integrator, "--spp", str(args.spp), "-D", "res=%d" % args.res,
           "-D", "spp=%d" % args.spp, "-t", str(args.threads), "--seed", str(seed), "--quiet"]
    if args.sampler:
        cmd += ["--sampler", args.sampler]
    for k, v in extra.items():
        cmd += ["-D", "%s=%s" % (k, v)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return np.array(mi.Bitmap(out), dtype=np.float64)[..., :3]


def figures(images, ref):
    stack = np.stack(images)
    norm = ref * ref + 0.01
    return dict(relmse=float(np.mean([relmse(x, ref) for x in images])),
                relvar=float(np.mean(stack.var(axis=0, ddof=1) / norm)),
                mean=[round(float(x), 5) for x in stack.mean(axis=(0, 1, 2)) / np.maximum(ref.mean(axis=(0, 1)), 1e-30)])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rcache", action="append", default=None, help="LABEL=BINARY (repeatable); default path=build/rcache")
    ap.add_argument("--scenes-dir", default=os.path.join(ROOT, "scenes"))
    ap.add_argument("--scenes", nargs="*", default=["envmap_product", "envmap_evening", "cornell_glossy", "corridor"])
    ap.add_argument("--res", type=int, default=128)
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--seeds", type=int, default=8)
    ap.add_argument("--spp-ref", type=int, default=4096)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--sampler", default=None, help="both renderers' sampler instead of the file's (independent, ldsampler)")
    ap.add_argument("--integrator", default="path", help="rcache's --integrator (e.g. rcache: its pilot's fallback)")
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--outdir", default="/tmp/rcache_equal_spp_noise")
    ap.add_argument("--json-out", default=None)
    ap.add_argument("--define", "-D", action="append", default=[], help="scene parameter name=value (both renderers)")
    args = ap.parse_args()
    builds = dict(b.split("=", 1) for b in (args.rcache or ["path=" + os.path.join(ROOT, "build", "rcache")]))

    import drjit as dr
    import mitsuba as mi
    mi.set_variant(args.variant)
    mi.set_log_level(mi.LogLevel.Warn)
    if args.variant.startswith("llvm"):
        dr.set_thread_count(args.threads)
    os.makedirs(args.outdir, exist_ok=True)
    extra = dict(d.split("=", 1) for d in args.define)
    seeds = range(1, args.seeds + 1)
    for name in args.scenes:
        scene_path = os.path.join(args.scenes_dir, name + ".xml")
        base = os.path.join(args.outdir, tag(name, args, extra))
        ref = mitsuba_image(mi, scene_path, "independent", args.spp_ref, 0, "%s_ref%d.exr" % (base, args.spp_ref), args, extra)
        if args.sampler:
            base += "_" + args.sampler  # the seeds' images, not the reference (always `independent`)
        mitsuba = [mitsuba_image(mi, scene_path, args.sampler, args.spp, s, "%s_mi%d_s%d.exr" % (base, args.spp, s), args, extra)
                   for s in seeds]
        row = dict(scene=name, res=args.res, spp=args.spp, seeds=args.seeds, spp_ref=args.spp_ref, defines=extra,
                   mitsuba=figures(mitsuba, ref))
        for label, binary in builds.items():
            images = [rcache_image(mi, binary, scene_path, s, "%s_%s_s%d.exr" % (base, label, s), args, extra) for s in seeds]
            f = figures(images, ref)
            f["relvar_ratio"] = round(f["relvar"] / row["mitsuba"]["relvar"], 3)
            f["relmse_ratio"] = round(f["relmse"] / row["mitsuba"]["relmse"], 3)
            row[label] = f
        line = json.dumps(row)
        print(line, flush=True)
        if args.json_out:
            with open(args.json_out, "a") as fh:
                fh.write(line + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
