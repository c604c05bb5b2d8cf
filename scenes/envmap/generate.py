#!/usr/bin/env python3
"""Writes the procedural data of the envmap-lit scenes (run from anywhere: python3 generate.py).

  sky_noon.exr    128×64 lat-long HDR sky: blue zenith to a pale horizon, a broad sun lobe 40° up,
                  a dark ground below a sharp horizon (the horizon row pair is where a renderer's
                  texel-centre convention shows).
  sky_evening.exr the same layout with a warm sun 12° above the horizon and a dimmer, redder sky.
  torus_knot.ply  a (2,3) torus knot tube with analytic per-vertex normals (binary PLY).

Lat-long layout as Mitsuba 3's envmap reads it: row 0 is the zenith (local +y), column x at
azimuth φ = 2π (x + 0.5) / W with direction (sinθ sinφ, cosθ, −sinθ cosφ). Pixels are written as
half floats, uncompressed scanlines, so the files stay small and any EXR reader opens them. Only the
Python standard library is used.
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def half_bits(x):
    return struct.unpack("<H", struct.pack("<e", x))[0]


def write_exr(path, width, height, pixel):
    """Scanline OpenEXR, HALF channels B, G, R (alphabetical, as the format requires), no compression."""
    def attr(name, kind, data):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data

    chlist = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 1, 0, 1, 1) for c in "BGR") + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2) + attr("channels", "chlist", chlist) +
              attr("compression", "compression", b"\0") + attr("dataWindow", "box2i", box) +
              attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", b"\0") +
              attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attr("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    line_bytes = 3 * 2 * width
    first = len(header) + 8 * height
    offsets = b"".join(struct.pack("<Q", first + y * (8 + line_bytes)) for y in range(height))
    body = bytearray()
    for y in range(height):
        row = [pixel(x, y) for x in range(width)]
        body += struct.pack("<ii", y, line_bytes)
        for c in (2, 1, 0):
            body += struct.pack("<%dH" % width, *(half_bits(p[c]) for p in row))
    with open(path, "wb") as f:
        f.write(header + offsets + bytes(body))
    print("%s: %dx%d, %d bytes" % (os.path.basename(path), width, height, os.path.getsize(path)))


def direction(u, v):
    theta, phi = v * math.pi, u * 2.0 * math.pi
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))


def sky(zenith, horizon, ground, sun_colour, sun_elevation_deg, sun_azimuth_deg, sun_width_deg):
    el, az = math.radians(sun_elevation_deg), math.radians(sun_azimuth_deg)
    sun = (math.cos(el) * math.sin(az), math.sin(el), -math.cos(el) * math.cos(az))
    width = math.radians(sun_width_deg)

    def pixel(x, y, W=128, H=64):
        # Texel centres: u = (x + 0.5) / W; v = y / (H − 1) (Mitsuba's rows lie on the poles).
        d = direction((x + 0.5) / W, y / (H - 1))
        if d[1] < 0.0:
            return ground
        t = 1.0 - d[1]  # 0 at the zenith, 1 at the horizon
        base = [zenith[c] + (horizon[c] - zenith[c]) * t ** 2 for c in range(3)]
        cos_g = max(-1.0, min(1.0, sum(a * b for a, b in zip(d, sun))))
        lobe = math.exp(-(math.acos(cos_g) / width) ** 2)  # a broad sun: several texels wide
        return tuple(base[c] + sun_colour[c] * lobe for c in range(3))
    return pixel


def torus_knot(path, p=2, q=3, R=0.55, r=0.22, tube=0.11, n_along=128, n_around=10):
    def centre(t):
        rr = R + r * math.cos(q * t)
        return (rr * math.cos(p * t), r * math.sin(q * t), rr * math.sin(p * t))

    verts, faces = [], []
    for i in range(n_along):
        t = 2.0 * math.pi * i / n_along
        c, c2 = centre(t), centre(t + 1e-3)
        tan = [b - a for a, b in zip(c, c2)]
        ln = math.sqrt(sum(x * x for x in tan))
        tan = [x / ln for x in tan]
        # A normal frame around the tangent (the knot never runs parallel to +y for long).
        up = (0.0, 1.0, 0.0)
        n1 = [up[1] * tan[2] - up[2] * tan[1], up[2] * tan[0] - up[0] * tan[2], up[0] * tan[1] - up[1] * tan[0]]
        l1 = math.sqrt(sum(x * x for x in n1))
        n1 = [x / l1 for x in n1]
        n2 = [tan[1] * n1[2] - tan[2] * n1[1], tan[2] * n1[0] - tan[0] * n1[2], tan[0] * n1[1] - tan[1] * n1[0]]
        for j in range(n_around):
            a = 2.0 * math.pi * j / n_around
            n = [math.cos(a) * n1[k] + math.sin(a) * n2[k] for k in range(3)]
            verts.append(([c[k] + tube * n[k] for k in range(3)], n))
    for i in range(n_along):
        for j in range(n_around):
            a = i * n_around + j
            b = ((i + 1) % n_along) * n_around + j
            c = ((i + 1) % n_along) * n_around + (j + 1) % n_around
            d = i * n_around + (j + 1) % n_around
            faces += [(a, b, c), (a, c, d)]
    header = ("ply\nformat binary_little_endian 1.0\ncomment (2,3) torus knot, generate.py\n"
              "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "property float nx\nproperty float ny\nproperty float nz\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(verts), len(faces)))
    with open(path, "wb") as f:
        f.write(header.encode())
        for pos, n in verts:
            f.write(struct.pack("<6f", *pos, *n))
        for tri in faces:
            f.write(struct.pack("<B3i", 3, *tri))
    print("%s: %d vertices, %d triangles, %d bytes" % (os.path.basename(path), len(verts), len(faces),
                                                       os.path.getsize(path)))


def main():
    write_exr(os.path.join(HERE, "sky_noon.exr"), 128, 64,
              sky(zenith=(0.18, 0.32, 0.75), horizon=(0.85, 0.9, 1.0), ground=(0.10, 0.09, 0.08),
                  sun_colour=(120.0, 110.0, 95.0), sun_elevation_deg=40.0, sun_azimuth_deg=215.0, sun_width_deg=4.0))
    write_exr(os.path.join(HERE, "sky_evening.exr"), 128, 64,
              sky(zenith=(0.05, 0.08, 0.22), horizon=(0.9, 0.55, 0.35), ground=(0.06, 0.05, 0.05),
                  sun_colour=(160.0, 80.0, 30.0), sun_elevation_deg=12.0, sun_azimuth_deg=120.0, sun_width_deg=5.0))
    torus_knot(os.path.join(HERE, "torus_knot.ply"))


if __name__ == "__main__":
    main()
