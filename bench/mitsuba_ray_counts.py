#!/usr/bin/env python3
"""Rays per camera sample of Mitsuba 3's `path` integrator, counted, next to rcache's own count.

Mitsuba has no ray statistics, so this runs the `path` integrator's loop (src/integrators/path.cpp)
as a wavefront over all of an image's samples in Python (llvm_ad_rgb) and counts, per bounce, the
lanes that Mitsuba traces:
  - closest-hit rays: the camera ray, then one extension ray per lane that survives the bounce
    (max_depth: a vertex extends only while depth + 1 < max_depth; Russian roulette from rr_depth on
    q = min(max(throughput) * eta^2, 0.95); a zero throughput ends the path);
  - shadow rays: one per vertex whose BSDF has a smooth lobe and whose emitter sample has a non-zero
    density (Scene::sample_emitter_direction traces it before the BSDF is evaluated).
The loop draws its own numbers, so the counts are those of the same estimator, not of the same paths.
`hide_emitters` camera rays that skip area emitters are not counted (no shipped scene hides them).

rcache's figures are its statistics `intersect_rays_per_sample` and `shadow_rays_per_sample`.

  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so \\
    /root/.cache/rcache/bench-venv/bin/python bench/mitsuba_ray_counts.py --rcache build/rcache \\
    [--res 64] [--spp 16] [--scenes corridor ...]
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

SCENES = ["envmap_product", "envmap_evening", "corridor", "cornell_glossy", "cornell_diffuse", "glossy_sweep",
          "aniso_sphere", "curved_glossy", "furnace"]


def integrator_depths(integrator):
    """max_depth and rr_depth of a path integrator, from its description (-1 = unbounded)."""
    text = str(integrator)
    depth = lambda name, default: int(re.search(name + r"\s*=\s*(-?\d+)", text).group(1)) if name in text else default
    return depth("max_depth", -1), depth("rr_depth", 5)


def mitsuba_counts(mi, dr, path, res, spp, seed):
    scene = mi.load_file(path, res=res, spp=spp)
    sensor = scene.sensors()[0]
    max_depth, rr_depth = integrator_depths(scene.integrator())
    if max_depth < 0:
        max_depth = 2**31 - 1
    size = sensor.film().crop_size()
    n = int(size[0]) * int(size[1]) * spp
    sampler = sensor.sampler().clone()
    sampler.seed(seed, n)
    idx = dr.arange(mi.UInt32, n) // spp
    pixel = mi.Vector2f(mi.Float(idx % int(size[0])), mi.Float(idx // int(size[0])))
    film_pos = (pixel + sampler.next_2d()) / mi.Vector2f(size)
    ray, _ = sensor.sample_ray(0.0, sampler.next_1d(), film_pos, sampler.next_2d())
    ctx = mi.BSDFContext()
    active = mi.Bool(True)
    depth = mi.UInt32(0)
    throughput = mi.Spectrum(1.0)
    eta = mi.Float(1.0)
    intersect, shadow = n, 0
    si = scene.ray_intersect(ray, active)
    while True:
        active_next = active & si.is_valid() & (depth + 1 < max_depth)
        if not dr.any(active_next):
            break
        bsdf = si.bsdf(ray)
        active_em = active_next & mi.has_flag(bsdf.flags(), mi.BSDFFlags.Smooth)
        ds, _ = scene.sample_emitter_direction(si, sampler.next_2d(), False, active_em)
        shadow += int(dr.count(active_em & (ds.pdf != 0.0))[0])
        sample1, sample2 = sampler.next_1d(), sampler.next_2d()
        bs, weight = bsdf.sample(ctx, si, sample1, sample2, active_next)
        throughput[active_next] *= weight
        eta[active_next] *= bs.eta
        depth[active_next] += 1
        t_max = dr.max(throughput)
        rr_prob = dr.minimum(t_max * eta * eta, 0.95)
        rr_active = depth >= rr_depth
        rr_continue = sampler.next_1d() < rr_prob
        throughput[active_next & rr_active] *= dr.rcp(rr_prob)
        active = active_next & (~rr_active | rr_continue) & (t_max != 0.0)
        ray = si.spawn_ray(si.to_world(bs.wo))
        intersect += int(dr.count(active)[0])
        si = scene.ray_intersect(ray, active)
        dr.eval(si, throughput, eta, depth, active, ray)
    return intersect / n, shadow / n


def rcache_counts(binary, path, res, spp):
    with tempfile.TemporaryDirectory() as tmp:
        stats = os.path.join(tmp, "stats.json")
        subprocess.run([binary, path, "--integrator", "path", "-D", f"res={res}", "--spp", str(spp), "--quiet",
                        "-o", os.path.join(tmp, "out.exr"), "--stats", stats], check=True, stdout=subprocess.DEVNULL)
        with open(stats) as f:
            d = json.load(f)
    d = d.get("stats", d)
    return d["intersect_rays_per_sample"], d["shadow_rays_per_sample"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rcache", default=None, help="an rcache binary, for its counts alongside")
    ap.add_argument("--res", type=int, default=64)
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scenes", nargs="*", default=SCENES)
    args = ap.parse_args()
    import drjit as dr
    import mitsuba as mi
    mi.set_variant("llvm_ad_rgb")
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    print("scene  mitsuba: intersect shadow total  |  rcache: intersect shadow total  |  rcache/mitsuba total")
    for s in args.scenes:
        path = os.path.join(root, "scenes", s + ".xml")
        mi_i, mi_s = mitsuba_counts(mi, dr, path, args.res, args.spp, args.seed)
        line = f"{s}  {mi_i:.4f} {mi_s:.4f} {mi_i + mi_s:.4f}"
        if args.rcache:
            rc_i, rc_s = rcache_counts(args.rcache, path, args.res, args.spp)
            line += f"  |  {rc_i:.4f} {rc_s:.4f} {rc_i + rc_s:.4f}  |  {(rc_i + rc_s) / (mi_i + mi_s):.4f}"
        print(line, flush=True)


if __name__ == "__main__":
    sys.exit(main())
