#!/usr/bin/env python3
"""The Mitsuba 3 side of the benchmark: one render as a user would script it, one process per image.

  python mitsuba_render.py SCENE.xml OUT.exr RES SPP SEED THREADS [VARIANT] [SAMPLER]

Loads the scene file with -D res/spp, renders with mi.render and writes an EXR. VARIANT defaults to
llvm_ad_rgb (needs DRJIT_LIBLLVM_PATH pointing at LLVM >= 17). SAMPLER, when given, replaces the
file's sampler type (the ground-truth reference uses `independent`). Images of more than 2^22
samples are rendered in passes of equal spp with consecutive seeds and averaged: one wavefront of
res² × spp lanes would need tens of GB; a pass's kernel is compiled once and reused.
"""
import os
import re
import sys


def main():
    scene_path, out, res, spp, seed, threads = sys.argv[1], sys.argv[2], *map(int, sys.argv[3:7])
    variant = sys.argv[7] if len(sys.argv) > 7 else "llvm_ad_rgb"
    sampler = sys.argv[8] if len(sys.argv) > 8 else None
    import drjit as dr
    import mitsuba as mi
    mi.set_variant(variant)
    if variant.startswith("llvm"):
        dr.set_thread_count(threads)
    load_path = scene_path
    if sampler:
        with open(scene_path) as f:
            text = re.sub(r'<sampler type="[a-z]+">', '<sampler type="%s">' % sampler, f.read())
        load_path = os.path.join(os.path.dirname(scene_path), ".mitsuba_%d_%s" % (os.getpid(), os.path.basename(scene_path)))
        with open(load_path, "w") as f:
            f.write(text)
    try:
        per_pass = spp
        while per_pass > 1 and res * res * per_pass > (1 << 22):
            per_pass //= 4 if per_pass % 4 == 0 else 2  # powers of 4 stay powers of 4 (ldsampler)
        scene = mi.load_file(load_path, res=res, spp=per_pass)
    finally:
        if load_path != scene_path:
            os.remove(load_path)
    passes = max(1, spp // per_pass)
    acc = None
    for k in range(passes):
        img = mi.render(scene, spp=per_pass, seed=seed * 65536 + k)
        acc = img if acc is None else acc + img
    mi.Bitmap(acc / passes if passes > 1 else acc).write(out)


if __name__ == "__main__":
    main()
