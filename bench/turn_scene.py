#!/usr/bin/env python3
"""Turned scenes: a copy of a Mitsuba 3 XML scene turned as a whole about the world origin, and
rcache's error on it against the same error on the original.

A cache that depends on the scene's orientation in world space (an axis-aligned octree, world-frame
SH, axis-aligned hemispheres, a z-up assumption) gives another error on the turned copy; a correct
one gives the same error up to noise.

Turning: every top-level <shape>, <sensor> and <emitter> gets one more <rotate> at the end of its
to_world (Mitsuba 3 composes a <transform>'s children left to right, each applied after the ones
before it, so the last child acts in world space; host/scene/transform_parser.cpp does the same).
Elements without a to_world get one; point/directional emitters given by position/direction get
those vectors rotated instead (Mitsuba forbids both). Relative file names become absolute so the
copy can live anywhere.

  turn_scene.py write SCENE.xml OUT.xml --axis X,Y,Z --angle DEG
  turn_scene.py measure [--scenes ...] [--res 64] [--spp 16] [--spp-ref 1024]
      renders original and turned copies with rcache (defaults) and the path tracer (reference),
      [--params fallback=false] [--mitsuba-spp N]
      renders original and turned copies with rcache (defaults, or -D params) and the path tracer
      (reference), prints relMSE, records, times and the per-16-px-block agreements; needs numpy +
      mitsuba (EXR reading, optional Mitsuba renders) from the bench venv.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BLOCK = 16
ROTATIONS = [("x90", (1, 0, 0), 90.0), ("oblique37", (1, 2, 3), 37.0), ("z180", (0, 0, 1), 180.0),
             ("y-61", (0, 1, 0), -61.0)]


def unit(axis):
    n = math.sqrt(sum(a * a for a in axis))
    return tuple(a / n for a in axis)


def rotate_vector(v, axis, angle_deg):
    """Rodrigues' rotation (right-handed, as Mitsuba's rotate)."""
    k = unit(axis)
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    dot = sum(a * b for a, b in zip(k, v))
    cross = (k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0])
    return tuple(v[i] * c + cross[i] * s + k[i] * dot * (1 - c) for i in range(3))


def parse_vec(text):
    return tuple(float(x) for x in text.replace(",", " ").split())


def turn_element(el, axis, angle):
    k = unit(axis)
    for name in ("position", "direction"):
        for p in el.findall("./*[@name='%s']" % name):
            v = rotate_vector(parse_vec(p.get("value")), axis, angle)
            p.set("value", "%.9g, %.9g, %.9g" % v)
            return
    tr = el.find("./transform[@name='to_world']")
    if tr is None:
        tr = ET.SubElement(el, "transform", name="to_world")
    ET.SubElement(tr, "rotate", x="%.9g" % k[0], y="%.9g" % k[1], z="%.9g" % k[2], angle="%.9g" % angle)


def turned_tree(scene_path, axis, angle):
    tree = ET.parse(scene_path)
    root = tree.getroot()
    base = os.path.dirname(os.path.abspath(scene_path))
    for el in root.iter("string"):
        if el.get("name") == "filename" and not os.path.isabs(el.get("value")) and "$" not in el.get("value"):
            el.set("value", os.path.join(base, el.get("value")))
    for el in root:
        if el.tag in ("include", "shapegroup") or (el.tag == "shape" and el.get("type") == "instance"):
            sys.exit("%s: <%s> is not turned by this script" % (scene_path, el.tag))
        if el.tag in ("shape", "sensor", "emitter"):
            turn_element(el, axis, angle)
    return tree


def write_turned(scene_path, out_path, axis, angle):
    turned_tree(scene_path, axis, angle).write(out_path)


def render(rcache, scene, integrator, spp, seed, res, out, threads, params=()):
    stats = out.replace(".exr", ".json")
    cmd = [rcache, scene, "--integrator", integrator, "--spp", str(spp), "--seed", str(seed), "-D", "res=%d" % res,
           "-t", str(threads), "--quiet", "-o", out, "--stats", stats]
    for p in params:
        cmd += ["-D", p]
    t0 = time.time()
    subprocess.run(cmd, check=True)
    wall = time.time() - t0
    with open(stats) as f:
        return json.load(f), wall


def load_exr(path):
    import mitsuba as mi
    import numpy as np
    mi.set_variant("scalar_rgb")
    return np.array(mi.Bitmap(path), dtype=np.float64)[..., :3]


def relmse(x, r):
    import numpy as np
    return float(np.mean((x - r) ** 2 / (r * r + 0.01)))


def block_ratio(img, ref):
    """Worst block/channel |block mean − reference block mean| over 4 % of the reference's block
    mean + 0.01 (the tolerance of tests/cache/turned_scene_test.cpp and the light split's tests)."""
    import numpy as np
    h, w, c = img.shape
    h2, w2 = h // BLOCK * BLOCK, w // BLOCK * BLOCK
    def means(a):
        return a[:h2, :w2].reshape(h2 // BLOCK, BLOCK, w2 // BLOCK, BLOCK, c).mean(axis=(1, 3))
    return float((np.abs(means(img) - means(ref)) / (0.04 * means(ref) + 0.01)).max())


def mitsuba_render(path, res, spp, out):
    """Mitsuba 3 (scalar_rgb) of the same file: the turned copy must be its original's picture
    in the peer's semantics too, not only in rcache's loader."""
    import mitsuba as mi
    import numpy as np
    mi.set_variant("scalar_rgb")
    img = np.array(mi.render(mi.load_file(path, res=res, spp=spp), seed=5), dtype=np.float64)[..., :3]
    np.save(out, img)
    return img


def measure(args):
    os.makedirs(args.outdir, exist_ok=True)
    rows = []
    for scene in args.scenes:
        src = os.path.join(ROOT, "scenes", scene + ".xml")
        variants = [("original", None, 0.0)] + [(n, a, g) for n, a, g in ROTATIONS if n in args.rotations]
        tag = scene + ("_" + "_".join(p.replace("=", "-") for p in args.params) if args.params else "")
        for name, axis, angle in variants:
            path = src
            if axis is not None:
                path = os.path.join(args.outdir, "%s_%s.xml" % (scene, name))
                write_turned(src, path, axis, angle)
            stem = os.path.join(args.outdir, "%s_%s" % (scene, name))
            rstem = os.path.join(args.outdir, "%s_%s" % (tag, name))
            if not os.path.exists(stem + "_ref.exr"):
                render(args.rcache, path, "path", args.spp_ref, 101, args.res, stem + "_ref.exr", args.threads)
            st_rc, wall_rc = render(args.rcache, path, "rcache", args.spp, 7, args.res, rstem + "_rc.exr", args.threads,
                                    args.params)
            st_pt, wall_pt = render(args.rcache, path, "path", args.spp, 7, args.res, stem + "_pt.exr", args.threads)
            ref, rc, pt = load_exr(stem + "_ref.exr"), load_exr(rstem + "_rc.exr"), load_exr(stem + "_pt.exr")
            row = dict(scene=scene, params=args.params, turn=name, relmse_rcache=relmse(rc, ref), relmse_path=relmse(pt, ref),
                       records=st_rc.get("records"), fallback=st_rc.get("fallback"), env_cache=st_rc.get("env_cache"),
                       wall_rcache_s=round(wall_rc, 2), wall_path_s=round(wall_pt, 2),
                       block_rcache_vs_ref=block_ratio(rc, ref))
            if axis is not None:
                orig = os.path.join(args.outdir, "%s_original" % scene)
                row["relmse_ref_vs_original_ref"] = relmse(ref, load_exr(orig + "_ref.exr"))
                row["block_ref_vs_original_ref"] = block_ratio(ref, load_exr(orig + "_ref.exr"))
                row["block_rcache_vs_original_rcache"] = block_ratio(
                    rc, load_exr(os.path.join(args.outdir, "%s_original_rc.exr" % tag)))
            if args.mitsuba_spp:
                import numpy as np
                mi_img = mitsuba_render(path, args.res, args.mitsuba_spp, stem + "_mi.npy")
                if axis is not None:
                    orig_mi = np.load(os.path.join(args.outdir, "%s_original_mi.npy" % scene))
                    row["mitsuba_relmse_vs_original"] = relmse(mi_img, orig_mi)
                    row["mitsuba_block_vs_original"] = block_ratio(mi_img, orig_mi)
            rows.append(row)
            print(json.dumps(row), flush=True)
    with open(os.path.join(args.outdir, "results_%s.json" % "_".join([s for s in args.scenes] + list(args.params))), "w") as f:
        json.dump(rows, f, indent=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    w = sub.add_parser("write")
    w.add_argument("scene")
    w.add_argument("out")
    w.add_argument("--axis", default="1,0,0")
    w.add_argument("--angle", type=float, default=90.0)
    m = sub.add_parser("measure")
    m.add_argument("--rcache", default=os.path.join(ROOT, "build", "rcache"))
    m.add_argument("--scenes", nargs="*", default=["cornell_glossy", "envmap_product"])
    m.add_argument("--rotations", nargs="*", default=[r[0] for r in ROTATIONS])
    m.add_argument("--res", type=int, default=64)
    m.add_argument("--spp", type=int, default=16)
    m.add_argument("--spp-ref", type=int, default=1024)
    m.add_argument("--threads", type=int, default=2)
    m.add_argument("--params", nargs="*", default=[], help="rcache -D parameters, e.g. fallback=false")
    m.add_argument("--mitsuba-spp", type=int, default=0, help="also render with Mitsuba 3 scalar_rgb (0: no)")
    m.add_argument("--outdir", default="/tmp/rcache_turned")
    args = ap.parse_args()
    if args.cmd == "write":
        write_turned(args.scene, args.out, parse_vec(args.axis), args.angle)
    else:
        measure(args)


if __name__ == "__main__":
    main()
