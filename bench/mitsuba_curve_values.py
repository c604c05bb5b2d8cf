"""Mitsuba 3.9.1 scalar_rgb ray hits on linearcurve / bsplinecurve shapes: the reference values of
tests/render/curve_test.cpp (t, p, n, uv, dp/du, dp/dv per ray; invalid = a miss).
  /root/.cache/rcache/bench-venv/bin/python bench/mitsuba_curve_values.py
"""
import os
import tempfile

import mitsuba as mi

mi.set_variant('scalar_rgb')

CURVES = {
    # along x from 0 to 1, radius 0.2: a capsule / (B-spline of evenly spaced collinear points) an open tube
    'linear': ('linearcurve', '0 0 0 0.2\n1 0 0 0.2\n'),
    'bspline': ('bsplinecurve', '-1 0 0 0.2\n0 0 0 0.2\n1 0 0 0.2\n2 0 0 0.2\n'),
    # a cone: radius 0.1 to 0.3 along x
    'cone': ('linearcurve', '0 0 0 0.1\n1 0 0 0.3\n'),
    # a bend in the xy plane with varying radius
    'bent': ('bsplinecurve', '0 0 0 0.05\n1 0 0 0.1\n2 1 0 0.2\n2 2 0 0.1\n'),
}
RAYS = {
    'linear': [((0.25, -5, 0), (0, 1, 0)), ((0.5, 0, 5), (0, 0, -1)), ((0.5, 0, 0), (0, 1, 0)),
               ((5, 0, 0), (-1, 0, 0)), ((1.1, -5, 0), (0, 1, 0)), ((0.3, -2, 0.05), (0.1, 1, 0.03))],
    'bspline': [((0.25, -5, 0), (0, 1, 0)), ((0.5, 0, 0), (0, 1, 0)), ((1.02, -5, 0), (0, 1, 0)),
                ((0.3, -2, 0.05), (0.1, 1, 0.03))],
    'cone': [((0.5, -5, 0), (0, 1, 0)), ((0.2, 0.1, 5), (0, 0, -1))],
    'bent': [((1.2, 0.3, 5), (0, 0, -1)), ((1.5, 0.5, 5), (0, 0, -1)), ((1.7, 0.9, 5), (0.1, 0, -1))],
}

tmp = tempfile.mkdtemp()
for name, (plugin, text) in CURVES.items():
    path = os.path.join(tmp, name + '.txt')
    with open(path, 'w') as f:
        f.write(text)
    scene = mi.load_dict({'type': 'scene', 'c': {'type': plugin, 'filename': path}})
    for o, d in RAYS[name]:
        norm = sum(x * x for x in d) ** 0.5
        si = scene.ray_intersect(mi.Ray3f(mi.Point3f(*o), mi.Vector3f(*[x / norm for x in d])))
        if not si.is_valid():
            print(name, o, d, 'miss')
            continue
        print(name, o, d, 't %.6f' % si.t, 'p', list(si.p), 'n', list(si.n), 'uv', list(si.uv),
              'dpdu', list(si.dp_du), 'dpdv', list(si.dp_dv))
