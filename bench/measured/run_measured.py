#!/usr/bin/env python3
"""Measured material: rcache vs rcache's path tracer on a MERL-format material, and Mitsuba 3
(llvm_ad_rgb) on its analytic twin; time to equal error.

Writes two scenes that differ only in the sphere's material: analytic.xml (a Beckmann rough
conductor, which Mitsuba renders) and measured.xml (<bsdf type="merl"> on measured.binary, the
same BSDF tabulated by build/merl_generate). The reference is Mitsuba's render of analytic.xml at
high spp; every method's error is its relMSE against it (so the measured renders carry the table's
discretisation error too). Runs are interleaved (one rung of each method in turn) because the
machine's cores are shared; compare the ratios, not the seconds. Times are render times: rcache's
"time_render_s" (its fill and final pass; the tables come from the disk cache, built by an untimed
first run) and Mitsuba's mi.render; scene loading (rcache: reading the 35 MB table and building its
sampler) is reported apart. The reference is kept in DIR/reference.npy for reruns.
Each rung runs --repeat times (rounds interleaved too) and keeps its shortest time, the least
disturbed by other processes; the error is the first round's. The highest rung of each method also
gets the per-16-px-block bias check: the largest |block mean − reference block mean| / reference.
Usage: bench/measured/run_measured.py [--out DIR] [--res N] [--ref-spp N] [--threads N] [--repeat N]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.path.join(ROOT, "build")

SCENE = """<scene version="3.0.0">
  <default name="spp" value="16"/>
  <default name="res" value="128"/>
  <integrator type="path"><integer name="max_depth" value="4"/></integrator>
  <sensor type="perspective">
    <float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 0.3, 3.6" target="0, -0.3, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="$spp"/></sampler>
    <film type="hdrfilm"><integer name="width" value="$res"/><integer name="height" value="$res"/>
      <rfilter type="box"/></film>
  </sensor>
  MATERIAL
  <bsdf type="diffuse" id="white"><rgb name="reflectance" value="0.75"/></bsdf>
  <bsdf type="diffuse" id="red"><rgb name="reflectance" value="0.75, 0.1, 0.1"/></bsdf>
  <bsdf type="diffuse" id="green"><rgb name="reflectance" value="0.1, 0.6, 0.1"/></bsdf>
  <shape type="sphere"><point name="center" value="0, -0.45, 0"/><float name="radius" value="0.55"/>
    <ref id="measured"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><translate y="-1"/></transform>
    <ref id="white"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="90"/><translate y="1"/></transform>
    <ref id="white"/></shape>
  <shape type="rectangle"><transform name="to_world"><translate z="-1"/></transform><ref id="white"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate y="1" angle="90"/><translate x="-1"/></transform>
    <ref id="red"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate y="1" angle="-90"/><translate x="1"/></transform>
    <ref id="green"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="0.3"/><rotate x="1" angle="90"/>
    <translate y="0.99"/></transform><ref id="white"/>
    <emitter type="area"><rgb name="radiance" value="15, 14, 12"/></emitter></shape>
</scene>
"""
ANALYTIC = """<bsdf type="roughconductor" id="measured"><string name="distribution" value="beckmann"/>
    <float name="alpha" value="0.3"/><rgb name="specular_reflectance" value="0.9, 0.6, 0.3"/></bsdf>"""
MEASURED = """<bsdf type="merl" id="measured"><string name="filename" value="measured.binary"/></bsdf>"""

# Rungs of each method, interleaved: rcache (cache defaults; spp sets the direct light's noise),
# the path tracer and Mitsuba at rising spp.
RCACHE_SPP = [4, 16, 64]
PATH_SPP = [16, 64, 256]
MITSUBA_SPP = [16, 64, 256]


def relmse(np, x, r):
    return float(np.mean((x - r) ** 2 / (r * r + 0.01)))


def worst_block_bias(np, x, r, b=16):
    h, w = r.shape[0] // b * b, r.shape[1] // b * b
    bx = x[:h, :w].reshape(h // b, b, w // b, b, 3).mean(axis=(1, 3))
    br = r[:h, :w].reshape(h // b, b, w // b, b, 3).mean(axis=(1, 3))
    return float(np.max(np.abs(bx - br) / np.maximum(br, 1e-3)))


def time_at(points, target):
    """Time at which a (time, error) curve reaches `target`, log-log interpolated (None if never)."""
    pts = sorted(points)
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e0 >= target >= e1 and e0 > e1:
            f = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
    if pts and pts[0][1] <= target:
        return pts[0][0]
    if len(pts) >= 2 and pts[-1][1] < pts[-2][1]:  # extrapolate along the last segment (~1/t)
        (t0, e0), (t1, e1) = pts[-2], pts[-1]
        slope = (math.log(e1) - math.log(e0)) / (math.log(t1) - math.log(t0))
        return math.exp(math.log(t1) + (math.log(target) - math.log(e1)) / slope)
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default=os.path.join(BUILD, "bench_measured"))
    ap.add_argument("--res", type=int, default=128)
    ap.add_argument("--ref-spp", type=int, default=2048)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=2)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    analytic = os.path.join(args.out, "analytic.xml")
    measured = os.path.join(args.out, "measured.xml")
    with open(analytic, "w") as f:
        f.write(SCENE.replace("MATERIAL", ANALYTIC))
    with open(measured, "w") as f:
        f.write(SCENE.replace("MATERIAL", MEASURED))
    binary = os.path.join(args.out, "measured.binary")
    subprocess.run([os.path.join(BUILD, "merl_generate"), analytic, "measured", binary], check=True)

    os.environ.setdefault("DRJIT_LIBLLVM_PATH", "/usr/lib/x86_64-linux-gnu/libLLVM-19.so")
    import drjit as dr
    import mitsuba as mi
    import numpy as np
    mi.set_variant("llvm_ad_rgb")
    dr.set_thread_count(args.threads)

    def mitsuba(spp, seed):
        scene = mi.load_file(analytic, res=args.res, spp=spp)
        t0 = time.perf_counter()
        img = mi.render(scene, spp=spp, seed=seed)
        dr.eval(img)
        arr = np.array(img, dtype=np.float64)[..., :3]
        return time.perf_counter() - t0, arr

    ref_path = os.path.join(args.out, f"reference_{args.res}_{args.ref_spp}.npy")
    if os.path.exists(ref_path):
        ref = np.load(ref_path)
    else:
        t0 = time.perf_counter()
        _, ref = mitsuba(args.ref_spp, 12345)
        np.save(ref_path, ref)
        print(f"reference: Mitsuba llvm_ad_rgb {args.ref_spp} spp, {time.perf_counter() - t0:.1f} s", flush=True)
    mitsuba(4, 1)  # warm-up: the JIT's kernels are cached after the first render

    def rcache(integrator, spp, seed, extra=()):
        out = os.path.join(args.out, f"{integrator}_{spp}.exr")
        stats = os.path.join(args.out, f"{integrator}_{spp}.json")
        cmd = [os.path.join(BUILD, "rcache"), measured, "-o", out, "--integrator", integrator, "--spp", str(spp),
               "-t", str(args.threads), "--seed", str(seed), "--quiet", "--stats", stats,
               "-D", f"res={args.res}", *extra]
        subprocess.run(cmd, check=True)
        img = np.array(mi.Bitmap(out), dtype=np.float64)[..., :3]
        st = json.load(open(stats))
        return st["time_render_s"], img, st

    # The BRDF tables are built once per material and kept in the disk cache; the first render
    # pays for them (reported), the timed rungs load them.
    _, _, st = rcache("rcache", 1, 99)
    print(f"rcache first run: load {st['time_load_s']:.2f} s; materials {json.dumps(st.get('materials', ''))}", flush=True)

    ladders = {"rcache": RCACHE_SPP, "path": PATH_SPP, "mitsuba": MITSUBA_SPP}
    times = {m: [math.inf] * len(RCACHE_SPP) for m in ladders}
    errors = {m: [None] * len(RCACHE_SPP) for m in ladders}
    bias = {}
    for rnd in range(args.repeat):
        for i in range(len(RCACHE_SPP)):
            for name in ("rcache", "path", "mitsuba"):
                spp = ladders[name][i]
                if name == "mitsuba":
                    t, img = mitsuba(spp, i + 1)
                else:
                    t, img, _ = rcache(name, spp, i + 1)
                times[name][i] = min(times[name][i], t)
                if rnd == 0:
                    errors[name][i] = relmse(np, img, ref)
                    if i == len(RCACHE_SPP) - 1:
                        bias[name] = worst_block_bias(np, img, ref)
                print(json.dumps({"round": rnd, "method": name, "spp": spp, "seconds": round(t, 3),
                                  "relmse": round(errors[name][i], 6)}), flush=True)
    curves = {m: list(zip(times[m], errors[m])) for m in ladders}
    for m in ladders:
        print(f"{m}: " + ", ".join(f"{spp} spp {t:.2f} s relMSE {e:.5f}" for spp, (t, e) in zip(ladders[m], curves[m]))
              + f"; worst 16-px block bias at {ladders[m][-1]} spp {100 * bias[m]:.1f}%")

    # Equal-error targets: the errors rcache reaches on its rungs.
    print("time to equal error (seconds; ratio = other / rcache):")
    for target in sorted({e for _, e in curves["rcache"]}, reverse=True):
        tr = time_at(curves["rcache"], target)
        tp = time_at(curves["path"], target)
        tm = time_at(curves["mitsuba"], target)
        fmt = lambda t: "n/a" if t is None else f"{t:.2f}"
        ratio = lambda t: "n/a" if t is None or tr is None else f"{t / tr:.2f}"
        print(f"  relMSE {target:.5f}: rcache {fmt(tr)}, path {fmt(tp)} ({ratio(tp)}x), "
              f"mitsuba {fmt(tm)} ({ratio(tm)}x)")


if __name__ == "__main__":
    sys.exit(main())
