"""Mitsuba 3.9.1 scalar_rgb eval/pdf of principled configurations: the reference values of
tests/bsdf/principled_test.cpp (si.wi = rcache's wo, wo = its wi).
  /root/.cache/rcache/bench-venv/bin/python bench/mitsuba_principled_values.py
"""
import math

import mitsuba as mi
mi.set_variant('scalar_rgb')
def d(ct, phi):
    s=math.sqrt(max(0,1-ct*ct)); return mi.Vector3f(s*math.cos(phi), s*math.sin(phi), ct)
base={'type':'principled','base_color':{'type':'rgb','value':[0.8,0.3,0.1]}}
def P(**k):
    q=dict(base); q.update(k); return q
cases=[
 (P(), 0.8,0.2, 0.6,3.0),
 (P(roughness=0.3, metallic=0.7, spec_tint=0.4), 0.7,0.1, 0.5,3.5),
 (P(roughness=0.4, clearcoat=0.8, clearcoat_gloss=0.6, sheen=0.5, sheen_tint=0.3), 0.5,1.0, 0.9,2.0),
 (P(roughness=0.35, anisotropic=0.6, flatness=0.4, specular=0.8), 0.6,0.3, 0.4,2.5),
 (P(roughness=0.3, spec_trans=0.6, eta=1.45), 0.7,0.4, -0.6,3.0),
 (P(roughness=0.3, spec_trans=0.6, eta=1.45), -0.7,0.4, -0.5,3.6),
 (P(roughness=0.3, spec_trans=0.6, eta=1.45), -0.7,0.4, 0.8,3.0),
]
ctx=mi.BSDFContext()
for p,co,po,ci,pi in cases:
    b=mi.load_dict(p)
    si=mi.SurfaceInteraction3f(); si.wi=d(co,po); si.sh_frame=mi.Frame3f(mi.Vector3f(0,0,1)); si.n=mi.Vector3f(0,0,1)
    v=b.eval(ctx,si,d(ci,pi)); pdf=b.pdf(ctx,si,d(ci,pi))
    kk={k:v2 for k,v2 in p.items() if k not in ('type','base_color')}
    print(kk, co,po,ci,pi, 'eval %.9g %.9g %.9g pdf %.9g' % (v[0],v[1],v[2],pdf))
