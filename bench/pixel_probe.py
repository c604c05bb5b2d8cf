#!/usr/bin/env python3
"""Per-pixel agreement of rcache's path tracer with Mitsuba 3 on a small probe scene (bench/pixel_probes/).

Each renderer renders --seeds images of --spp samples; a pixel's noise is the scatter of its seed
images (standard error of their mean), so per pixel and channel
    z = (mean_rcache − mean_mitsuba) / √(se_rcache² + se_mitsuba² + (10⁻⁴·mean_mitsuba)²)
(the last term: float rounding where both are noiseless, e.g. inside an emitter). With 16 seeds z is
Student's t with ~30 degrees of freedom: about 0.02 % of pixel-channels beyond 4 when the renderers
agree. A systematic difference in how a pixel is formed (camera rays, filter, sample positions,
emitter edges) shows as a cluster of |z| > 4 along edges.

  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so /root/.cache/rcache/bench-venv/bin/python \\
      bench/pixel_probe.py bench/pixel_probes/rect_gaussian.xml --variant llvm_ad_rgb [--seeds 16 --spp 1024]
Images are kept in --work (reused when present: delete them after changing rcache).
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

MITSUBA_SNIPPET = r"""
import os, sys, mitsuba as mi
mi.set_variant(sys.argv[1])
scene = mi.load_file(sys.argv[2])
for seed in range(int(sys.argv[4])):
    if not os.path.exists(sys.argv[5] % seed):
        mi.Bitmap(mi.render(scene, spp=int(sys.argv[3]), seed=100 + seed)).write(sys.argv[5] % seed)
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("--rcache", default="build/rcache")
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--seeds", type=int, default=16)
    ap.add_argument("--spp", type=int, default=1024)
    ap.add_argument("--work", default="/tmp/rcache_pixel_probe")
    ap.add_argument("--integrator", default="path", help="rcache's --integrator (e.g. the file's `direct`)")
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.scene))[0]
    mpat = os.path.join(args.work, "%s_%s_%d_s%%d.exr" % (name, args.variant, args.spp))
    rpat = os.path.join(args.work, "%s_rcache_%d_s%%d.exr" % (name, args.spp))
    subprocess.run([sys.executable, "-c", MITSUBA_SNIPPET, args.variant, args.scene, str(args.spp), str(args.seeds), mpat],
                   check=True)
    for s in range(args.seeds):
        if not os.path.exists(rpat % s):
            subprocess.run([args.rcache, args.scene, "--integrator", args.integrator, "--spp", str(args.spp), "--seed", str(s + 1),
                            "--quiet", "-o", rpat % s], check=True)
    import mitsuba as mi
    mi.set_variant("scalar_rgb")

    def stack(pattern):
        return np.stack([np.array(mi.Bitmap(pattern % s), dtype=np.float64)[..., :3] for s in range(args.seeds)])

    R, M = stack(rpat), stack(mpat)
    mr, mm = R.mean(0), M.mean(0)
    se2 = R.var(0, ddof=1) / args.seeds + M.var(0, ddof=1) / args.seeds + (1e-4 * mm) ** 2
    z = (mr - mm) / np.sqrt(np.maximum(se2, 1e-30))
    z[np.abs(mr - mm) < 1e-7] = 0.0
    worst = np.unravel_index(np.argmax(np.abs(z)), z.shape)
    print(json.dumps({"scene": name, "variant": args.variant, "seeds": args.seeds, "spp": args.spp,
                      "mean_ratio": np.round(mr.mean((0, 1)) / np.maximum(mm.mean((0, 1)), 1e-12), 4).tolist(),
                      "rms_z": round(float(np.sqrt((z ** 2).mean())), 2), "beyond_4": int((np.abs(z) > 4).sum()),
                      "pixel_channels": int(z.size), "max_abs_z": round(float(np.abs(z[worst])), 1),
                      "at_yxc": [int(v) for v in worst], "rcache_mitsuba_there": [round(float(mr[worst]), 4), round(float(mm[worst]), 4)]}))


if __name__ == "__main__":
    main()
