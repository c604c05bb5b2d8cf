#!/usr/bin/python3
"""The README's animated strip: the walk-through benchmark's frames (bench/walk/walk_bench.py --out DIR),
rcache with one shared cache beside the path tracer at equal time, as one looping GIF.
Written with Pillow (Debian's python3-pil): Debian 12 here has neither ffmpeg nor ImageMagick
installed, and a 96-pixel GIF needs no video encoder.
Usage: bench/walk/make_gif.py [--out bench/walk/out] [--gif docs/img/walk.gif] [--frames 24]
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import rcache_dask  # noqa: E402  (read_exr)


def to_srgb8(linear):
    c = np.clip(linear, 0.0, 1.0)
    srgb = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
    return (srgb * 255 + 0.5).astype(np.uint8)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--out", default=os.path.join(HERE, "out"))
    p.add_argument("--gif", default=os.path.join(ROOT, "docs", "img", "walk.gif"))
    p.add_argument("--frames", type=int, default=24)
    p.add_argument("--ms", type=int, default=120, help="display time per frame")
    a = p.parse_args()
    from PIL import Image
    images = []
    for f in range(a.frames):
        pair = [rcache_dask.read_exr(os.path.join(a.out, "%s_%04d.exr" % (name, f))) for name in ("shared", "path")]
        gap = np.ones((pair[0].shape[0], 4, 3), dtype=np.float32)
        images.append(Image.fromarray(to_srgb8(np.concatenate([pair[0], gap, pair[1]], axis=1))))
    # One palette for every frame (adaptive, from the first), no dithering: dithering noise that
    # changes from frame to frame would itself read as flicker.
    palette = images[0].quantize(colors=255, method=Image.Quantize.MEDIANCUT)
    frames = [im.quantize(palette=palette, dither=Image.Dither.NONE) for im in images]
    frames[0].save(a.gif, save_all=True, append_images=frames[1:], duration=a.ms, loop=0, optimize=False)
    print("wrote %s: %d frames, %dx%d (left: rcache, one shared cache; right: path tracer at equal time)"
          % (a.gif, len(frames), images[0].width, images[0].height))


if __name__ == "__main__":
    main()
