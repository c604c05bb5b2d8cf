#!/usr/bin/env python3
"""Does an estimator have another's expectation? Image means of independent-seed renders.

  bench/mean_agreement.py A1.exr,A2.exr,... B1.exr,B2.exr,...     # A (test) against B (reference)
  bench/mean_agreement.py --paired NEW1.exr,... OLD1.exr,...       # same seeds, two builds
  bench/mean_agreement.py --noise A1.exr,A2.exr,...               # noise of one render

Default: per channel the mean over the seeds of each set's image mean, its standard error from the
seeds' spread, the ratio A/B and z = difference / combined standard error; then per 16-px block the
ratio and z of the channels' sum (needs two or more images in each set). --paired: the mean over
seed pairs of NEW's image mean ÷ OLD's, per channel, with its standard error (a change's effect with
the seeds' noise cancelled), then NEW − OLD per 16-px block and channel in % with its z. --noise:
the per-pixel relative variance across the seeds, averaged over the image (the variance of one
render). Needs numpy and Mitsuba 3 (reads EXR through
mitsuba.Bitmap), e.g. /root/.cache/rcache/bench-venv/bin/python.
"""
import argparse

import mitsuba as mi
import numpy as np

BLOCK = 16


def load(path):
    return np.array(mi.Bitmap(path), dtype=np.float64)[..., :3]


def seed_stats(images):
    means = np.array([im.reshape(-1, 3).mean(0) for im in images])
    se = means.std(0, ddof=1) / np.sqrt(len(means)) if len(means) > 1 else np.zeros(3)
    return means.mean(0), se


def block_channels(im):
    h, w = im.shape[0] // BLOCK * BLOCK, im.shape[1] // BLOCK * BLOCK
    return im[:h, :w].reshape(h // BLOCK, BLOCK, w // BLOCK, BLOCK, 3).mean((1, 3))


def blocks(im):
    return block_channels(im).sum(-1)


def paired_blocks(new, old):
    # Per block and channel: the mean over seed pairs of NEW − OLD, in % of OLD's mean, and its z
    # from the pairs' spread (a local change with the seeds' noise cancelled as far as the two share it).
    d = np.array([block_channels(n) - block_channels(o) for n, o in zip(new, old)])
    ref = np.mean([block_channels(o) for o in old], 0)
    z = d.mean(0) / (d.std(0, ddof=1) / np.sqrt(len(d)) + 1e-30)
    np.set_printoptions(linewidth=200, precision=3, suppress=True)
    for c, name in enumerate("RGB"):
        print(f"{BLOCK}-px blocks, {name}: NEW - OLD in % of OLD\n", 100 * d.mean(0)[..., c] / ref[..., c])
        print(f"  z\n", z[..., c])


def compare(a, b):
    ma, sa = seed_stats(a)
    mb, sb = seed_stats(b)
    print("mean A", ma, "±", sa)
    print("mean B", mb, "±", sb)
    print("ratio A/B per channel", np.round(ma / mb, 5), "z", np.round((ma - mb) / np.sqrt(sa**2 + sb**2 + 1e-30), 2))
    if len(a) < 2 or len(b) < 2:
        return
    ab, bb = np.array([blocks(x) for x in a]), np.array([blocks(x) for x in b])
    se = np.sqrt(ab.var(0, ddof=1) / len(a) + bb.var(0, ddof=1) / len(b))
    np.set_printoptions(linewidth=200, precision=4, suppress=True)
    print(f"{BLOCK}-px block ratio A/B (channel sum):\n", ab.mean(0) / bb.mean(0))
    print("block z:\n", (ab.mean(0) - bb.mean(0)) / se)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--paired", action="store_true")
    ap.add_argument("--noise", action="store_true")
    ap.add_argument("sets", nargs="+")
    args = ap.parse_args()
    mi.set_variant("scalar_rgb")
    sets = [[load(p) for p in s.split(",")] for s in args.sets]
    if args.noise:
        stack = np.array(sets[0])
        m = stack.mean(0)
        print("per-pixel relative variance of one render:", (stack.var(0, ddof=1) / np.maximum(m, 1e-4) ** 2).mean())
    elif args.paired:
        r = np.array([n.reshape(-1, 3).mean(0) / o.reshape(-1, 3).mean(0) for n, o in zip(sets[0], sets[1])])
        print("NEW/OLD image mean per channel", np.round(r.mean(0), 5), "±", np.round(r.std(0, ddof=1) / np.sqrt(len(r)), 5))
        if len(r) > 1:
            paired_blocks(sets[0], sets[1])
    else:
        compare(sets[0], sets[1])


if __name__ == "__main__":
    main()
