#!/usr/bin/env python3
"""What an order-3 (bands 0..2) irradiance misses of a scene's environment map at given normals.

For each normal n: E = ∫_H(n) L(ω) cos θ dω (quadrature over the hemisphere) and E_bands, the same
irradiance from L's SH bands 0..2 over that hemisphere (Â_0..2 = π, 2π/3, π/4). Prints E_bands/E
per channel for the whole map and for rcache's cached part (texels clamped to luminance τ, as
host/cache/light_split.cpp does; τ from `rcache --stats`, env_threshold). No occlusion: the sky as
an open floor (normal +z) or a surface of that normal sees it.

  bench/cosine_truncation.py SCENE.xml --tau 1.16949 [--normal 0,0,1 ...] [--res 64]
Needs Mitsuba 3 (scalar_rgb), e.g. /root/.cache/rcache/bench-venv/bin/python.
"""
import argparse

import mitsuba as mi
import numpy as np

LUM = np.array([0.2126, 0.7152, 0.0722])
BANDS = [(0, np.pi), (1, 2 * np.pi / 3), (2, np.pi / 4)]


def frame(n):
    n = np.asarray(n, float) / np.linalg.norm(n)
    t = np.cross(n, [0.3, 0.5, 0.8])
    t /= np.linalg.norm(t)
    return t, np.cross(n, t), n


def ratios(emitter, n, res):
    # Midpoint quadrature, uniform in cos θ and φ: each cell 2π/(M·N) of solid angle.
    M, N = res, 2 * res
    ct = (np.arange(M) + 0.5) / M
    ph = 2 * np.pi * (np.arange(N) + 0.5) / N
    CT, PH = np.meshgrid(ct, ph, indexing="ij")
    ST = np.sqrt(1 - CT**2)
    t, b, nn = frame(n)
    dirs = (ST * np.cos(PH))[..., None] * t + (ST * np.sin(PH))[..., None] * b + CT[..., None] * nn
    si = mi.SurfaceInteraction3f()
    L = np.zeros(dirs.shape)
    for i in range(M):
        for j in range(N):
            si.wi = mi.Vector3f(-dirs[i, j])
            L[i, j] = np.array(emitter.eval(si))
    w = 2 * np.pi / (M * N)
    E = (L * CT[..., None]).sum((0, 1)) * w
    E_bands = np.zeros(3)
    for l, A in BANDS:
        y = np.sqrt((2 * l + 1) / (4 * np.pi)) * np.polynomial.legendre.legval(CT, [0] * l + [1])
        E_bands += A * (L * y[..., None]).sum((0, 1)) * w * np.sqrt((2 * l + 1) / (4 * np.pi))
    return E, E_bands / E


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("--tau", type=float, required=True)
    ap.add_argument("--normal", action="append", default=[])
    ap.add_argument("--res", type=int, default=64)
    args = ap.parse_args()
    mi.set_variant("scalar_rgb")
    scene = mi.load_file(args.scene)
    env = [e for e in scene.emitters() if e.is_environment()][0]
    params = mi.traverse(env)
    key = [k for k in params.keys() if k.endswith("data")][0]
    full = np.array(params[key], dtype=np.float64)
    scale = params[[k for k in params.keys() if k.endswith("scale")][0]]
    normals = [list(map(float, s.split(","))) for s in args.normal] or [[0, 0, 1]]
    lum = (full[..., :3] * scale) @ LUM
    cached = full.copy()
    over = lum > args.tau
    cached[over, :3] *= (args.tau / lum[over])[:, None]
    for name, data in [("whole map", full), ("cached part", cached)]:
        params[key] = mi.TensorXf(data.astype(np.float32))
        params.update()
        for n in normals:
            E, r = ratios(env, n, args.res)
            print(f"{name:11s} n={n}: E {np.round(E, 4)}  E_bands/E {np.round(r, 4)}")


if __name__ == "__main__":
    main()
