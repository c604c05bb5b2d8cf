"""Mitsuba 3.9.1 ray hits on an sdfgrid: the reference values of tests/render/sdf_grid_test.cpp
(t, n, sh_frame.n per ray and normals mode; invalid = a miss). The grid is the distance to a
sphere of radius 0.3 about (0.45, 0.5, 0.55) on 7×5×7 samples at (i/6, j/4, k/6), as float32; it is
placed by a non-uniform to_world, and once more inside a shapegroup by an instance that also turns it.
  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so \
      /root/.cache/rcache/bench-venv/bin/python bench/mitsuba_sdfgrid_values.py
"""
import math
import os
import struct
import tempfile

import mitsuba as mi

mi.set_variant('llvm_ad_rgb')

RES = (7, 5, 7)
CENTRE, RADIUS = (0.45, 0.5, 0.55), 0.3


def distance(i, j, k):
    x, y, z = i / (RES[0] - 1.0) - CENTRE[0], j / (RES[1] - 1.0) - CENTRE[1], k / (RES[2] - 1.0) - CENTRE[2]
    return math.sqrt(x * x + y * y + z * z) - RADIUS


path = os.path.join(tempfile.mkdtemp(), 'sphere.vol')
with open(path, 'wb') as f:
    f.write(b'VOL' + bytes([3]) + struct.pack('<iiiii', 1, *RES, 1) + struct.pack('<6f', 0, 0, 0, 1, 1, 1))
    for k in range(RES[2]):
        for j in range(RES[1]):
            for i in range(RES[0]):
                f.write(struct.pack('<f', distance(i, j, k)))

T = mi.ScalarTransform4f
PLACED = T().translate([1, -2, 0.5]) @ T().scale([2, 1, 1.5])
INSTANCE = T().translate([0, 1, 0]) @ T().rotate([0, 0, 1], 30) @ T().scale([1, 0.5, 2])
# Rays toward object points near the sphere's surface from a few directions, taken to the world of
# each placement and printed as they are cast (origin, unit direction). None hits a voxel face
# exactly: there the analytic normal (the gradient of one voxel) depends on which voxel, and
# Mitsuba picks it from the float rounding of the hit point.
TARGETS = [(0.47, 0.52, 0.85), (0.7, 0.6, 0.5), (0.3, 0.3, 0.45), (0.55, 0.75, 0.7)]
DIRS = [(0, 0, -1), (-0.3, 0.2, -1), (1, 0.1, 0.2), (0.1, -1, -0.3)]


def rays(placement):
    out = []
    for target, d in zip(TARGETS, DIRS):
        t = placement @ mi.ScalarPoint3f(*target)
        w = placement @ mi.ScalarVector3f(*d)
        w = w / math.sqrt(w.x * w.x + w.y * w.y + w.z * w.z)
        out.append((t - 4 * w, w))
    return out


for normals in ('analytic', 'smooth'):
    grid = {'type': 'sdfgrid', 'filename': path, 'normals': normals}
    scenes = {
        'placed': {'type': 'scene', 's': dict(grid, to_world=PLACED)},
        'instanced': {'type': 'scene', 'g': {'type': 'shapegroup', 's': grid},
                      'i': {'type': 'instance', 'to_world': INSTANCE, 'group': {'type': 'ref', 'id': 'g'}}},
    }
    for name, desc in scenes.items():
        scene = mi.load_dict(desc)
        for o, d in rays(PLACED if name == 'placed' else INSTANCE):
            si = scene.ray_intersect(mi.Ray3f(mi.Point3f(o), mi.Vector3f(d)))
            v = lambda a: '{%.7g, %.7g, %.7g}' % (a[0], a[1], a[2])
            w = lambda a: '{%.7g, %.7g, %.7g}' % (a.x[0], a.y[0], a.z[0])
            if not si.is_valid()[0]:
                print(normals, name, v(o), v(d), 'miss')
                continue
            print('{"%s", "%s", %s, %s, %.6f, %s, %s},' % (normals, name, v(o), v(d), si.t[0], w(si.n), w(si.sh_frame.n)))
