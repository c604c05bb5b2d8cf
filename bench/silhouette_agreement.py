#!/usr/bin/env python3
"""Where near an object's silhouette do two estimators differ? Means by distance to the silhouette.

  bench/silhouette_agreement.py A1.exr,A2.exr,... B1.exr,B2.exr,...            # A against B
  bench/silhouette_agreement.py --paired NEW1.exr,... OLD1.exr,...             # same seeds

The object is the set of pixels of B's mean image whose channel --object-channel exceeds
--object-ratio times channel 0 (e.g. a blue diffuse object on a grey floor: blue > 1.6 red). Every
pixel gets its signed distance to the object's silhouette in pixels (negative inside); per band of
distance and per channel: the mean over the seeds of each set's band mean, A − B in % of B, and z
(from both sets' seed spreads, or with --paired from the pairs' spread: a local change with the
seeds' noise cancelled as far as the two share it). The first band outside the object is split at
the object's centroid row (floor behind / in front of it). Needs numpy and Mitsuba 3 (reads EXR
through mitsuba.Bitmap), e.g. /root/.cache/rcache/bench-venv/bin/python.
"""
import argparse

import mitsuba as mi
import numpy as np

BANDS = [(-1e9, -3), (-3, -1.5), (-1.5, 0), (0, 1.5), (1.5, 3), (3, 6), (6, 1e9)]


def load(path):
    return np.array(mi.Bitmap(path), dtype=np.float64)[..., :3]


def signed_distance(obj):
    yy, xx = np.mgrid[: obj.shape[0], : obj.shape[1]]

    def dist(mask):  # every pixel's distance to the nearest pixel of mask (small images: brute force)
        py, px = np.nonzero(mask)
        return np.sqrt((yy[..., None] - py) ** 2 + (xx[..., None] - px) ** 2).min(-1)

    return np.where(obj, -dist(~obj), dist(obj)), yy


def report(name, a, b, paired):
    d = a.mean(0) - b.mean(0)
    se = (a - b).std(0, ddof=1) / np.sqrt(len(a)) if paired else np.sqrt(
        a.var(0, ddof=1) / len(a) + b.var(0, ddof=1) / len(b))
    print(f"{name:34s} A−B % {np.round(100 * d / b.mean(0), 3)}  z {np.round(d / se, 2)}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--paired", action="store_true")
    ap.add_argument("--object-channel", type=int, default=2)
    ap.add_argument("--object-ratio", type=float, default=1.6)
    ap.add_argument("a")
    ap.add_argument("b")
    args = ap.parse_args()
    mi.set_variant("scalar_rgb")
    A = np.array([load(p) for p in args.a.split(",")])
    B = np.array([load(p) for p in args.b.split(",")])
    if args.paired and len(A) != len(B):
        raise SystemExit("--paired needs as many images in each set")
    mean = B.mean(0)
    obj = mean[..., args.object_channel] > args.object_ratio * mean[..., 0]
    signed, yy = signed_distance(obj)
    centre = np.nonzero(obj)[0].mean()
    print(f"object pixels {obj.sum()}, seeds {len(A)} / {len(B)}")
    for lo, hi in BANDS:
        m = (signed > lo) & (signed <= hi)
        report(f"distance ({lo:g}, {hi:g}] px, {m.sum()} px", A[:, m].mean(1), B[:, m].mean(1), args.paired)
    for name, side in (("behind (rows above centroid)", yy < centre), ("in front (rows below)", yy >= centre)):
        m = (signed > 0) & (signed <= 1.5) & side
        report(f"(0, 1.5] {name}, {m.sum()} px", A[:, m].mean(1), B[:, m].mean(1), args.paired)


if __name__ == "__main__":
    main()
