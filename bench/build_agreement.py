#!/usr/bin/env python3
"""Do two rcache builds render the same estimator? (a measurement script, for changes that alter
float rounding or random-number use, so images cannot be compared bit for bit).

  /root/.cache/rcache/bench-venv/bin/python bench/build_agreement.py --old OLD/rcache --new NEW/rcache \
      [--scenes envmap_product corridor] [--res 64 --spp 64 --spp-ref 2048] [--integrator path]

Per scene: ref = the old build at --spp-ref (seed 1000); old1, old2 = the old build at --spp (seeds 1,
2): its own error and pixel noise; new = the new build at --spp (seed 3). The checks of
bench/mitsuba_crosscheck.py with the old build in Mitsuba's place: relMSE(new, ref) <= 1.3 x
relMSE(old1, ref), and every 16x16 block mean of new within 4 x the expected block error (from the
old build's noise) of ref. Reading EXR files needs the bench venv's mitsuba (scalar_rgb).
"""
import argparse
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mitsuba_crosscheck import block_check, relmse  # noqa: E402  (one definition of the checks)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def render(binary, scene, spp, seed, args, out):
    cmd = [binary, scene, "--integrator", args.integrator, "--spp", str(spp), "-D", "res=%d" % args.res,
           "--seed", str(seed), "-t", str(args.threads), "-o", out, "--quiet"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--old", required=True)
    ap.add_argument("--new", default=os.path.join(ROOT, "build", "rcache"))
    ap.add_argument("--scenes", nargs="*", default=["envmap_product"])
    ap.add_argument("--integrator", default="path")
    ap.add_argument("--res", type=int, default=64)
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--spp-ref", type=int, default=2048)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--outdir", default="/tmp/rcache_build_agreement")
    args = ap.parse_args()
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    os.makedirs(args.outdir, exist_ok=True)
    failures = 0
    for name in args.scenes:
        scene = os.path.join(ROOT, "scenes", name + ".xml")
        runs = {"ref": (args.old, args.spp_ref, 1000), "old1": (args.old, args.spp, 1), "old2": (args.old, args.spp, 2),
                "new": (args.new, args.spp, 3)}
        img = {}
        for key, (binary, spp, seed) in runs.items():
            path = os.path.join(args.outdir, "%s_%s.exr" % (name, key))
            render(binary, scene, spp, seed, args, path)
            img[key] = np.array(mi.Bitmap(path), dtype=np.float64)[..., :3]
        ref = img["ref"]
        row = dict(scene=name, relmse_new=relmse(img["new"], ref), relmse_old=relmse(img["old1"], ref),
                   **block_check(img["new"], ref, img["old1"], img["old2"], args.spp, args.spp_ref))
        row["pass"] = row["relmse_new"] <= 1.3 * row["relmse_old"] and row["block_max_ratio"] <= 4.0
        failures += not row["pass"]
        print(row, flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
