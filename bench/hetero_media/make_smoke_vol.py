#!/usr/bin/env python3
"""Writes the smoke grids of bench/hetero_media/*.xml (Mitsuba's `.vol`, version 3, float32).

  python3 make_smoke_vol.py OUT_DIR

smoke.vol: 16³ voxels, 1 channel, a lumpy blob: a Gaussian of width 0.3 around the cube's centre,
modulated by products of sines (the lumps), clamped at 0, maximum 1. smoke_rgb.vol: the same blob in
3 channels scaled by 1, 0.6, 0.25 (an extinction that differs per colour: Mitsuba's spectral MIS).
Deterministic, no randomness: the scenes render the same grid everywhere.
"""
import math
import os
import struct
import sys

N = 16


def density(x, y, z):
    r2 = (x - 0.5) ** 2 + (y - 0.5) ** 2 + (z - 0.5) ** 2
    lumps = 0.6 + 0.4 * math.sin(11.0 * x) * math.sin(7.0 * y + 1.0) * math.sin(9.0 * z + 2.0)
    return max(0.0, math.exp(-r2 / (2 * 0.3 ** 2)) * lumps)


def write(path, channel_scales):
    values = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                d = density((i + 0.5) / N, (j + 0.5) / N, (k + 0.5) / N)
                values.append(d)
    peak = max(values)
    with open(path, "wb") as f:
        f.write(b"VOL" + bytes([3]))
        f.write(struct.pack("<iiiii", 1, N, N, N, len(channel_scales)))
        f.write(struct.pack("<6f", 0, 0, 0, 1, 1, 1))
        for v in values:
            f.write(struct.pack("<%df" % len(channel_scales), *[v / peak * s for s in channel_scales]))


def main():
    out = sys.argv[1]
    write(os.path.join(out, "smoke.vol"), [1.0])
    write(os.path.join(out, "smoke_rgb.vol"), [1.0, 0.6, 0.25])


if __name__ == "__main__":
    main()
