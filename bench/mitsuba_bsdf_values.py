"""Mitsuba 3.9.1 scalar_rgb eval/pdf of roughdielectric and mask configurations: the reference values
of tests/bsdf/roughdielectric_test.cpp and mask_null_test.cpp (si.wi = rcache's wo, wo = its wi).
  /root/.cache/rcache/bench-venv/bin/python bench/mitsuba_bsdf_values.py
"""
import math

import mitsuba as mi
mi.set_variant('scalar_rgb')
def d(ct, phi):
    s=math.sqrt(max(0,1-ct*ct)); return mi.Vector3f(s*math.cos(phi), s*math.sin(phi), ct)
cases=[
 ({'type':'roughdielectric','distribution':'ggx','alpha':0.3}, d(0.8,0.2), d(0.6,3.0)),
 ({'type':'roughdielectric','distribution':'ggx','alpha':0.3}, d(0.8,0.2), d(-0.7,2.9)),
 ({'type':'roughdielectric','distribution':'beckmann','alpha':0.2,'int_ior':'water'}, d(-0.5,1.0), d(0.4,4.0)),
 ({'type':'roughdielectric','distribution':'beckmann','alpha':0.2,'int_ior':'water'}, d(-0.5,1.0), d(-0.9,4.5)),
 ({'type':'roughdielectric','distribution':'ggx','alpha_u':0.1,'alpha_v':0.4,'int_ior':1.7,'ext_ior':1.2}, d(0.3,0.5), d(-0.8,3.5)),
 ({'type':'mask','opacity':0.3,'nested':{'type':'roughconductor','alpha':0.2}}, d(0.7,0.1), d(0.6,3.3)),
]
ctx=mi.BSDFContext()
for p,wi,wo in cases:
    b=mi.load_dict(p)
    si=mi.SurfaceInteraction3f(); si.wi=wi; si.sh_frame=mi.Frame3f(mi.Vector3f(0,0,1)); si.n=mi.Vector3f(0,0,1)
    v=b.eval(ctx,si,wo); pdf=b.pdf(ctx,si,wo)
    print(p, [float(x) for x in wi], [float(x) for x in wo], 'eval', [float(x) for x in v], 'pdf', float(pdf))

# pplastic (tests/bsdf/pplastic_test.cpp) and polarizer (its sample weight; eval is 0 in RGB mode).
pcases=[
 ({'type':'pplastic','diffuse_reflectance':{'type':'rgb','value':[0.05,0.03,0.1]},'alpha':0.06}, d(0.8,0.2), d(0.75,3.3)),
 ({'type':'pplastic','diffuse_reflectance':{'type':'rgb','value':[0.05,0.03,0.1]},'alpha':0.06}, d(0.5,0.2), d(0.9,1.0)),
 ({'type':'pplastic','distribution':'ggx','alpha':0.3,'int_ior':1.7,'diffuse_reflectance':{'type':'rgb','value':[0.6,0.4,0.2]},
   'specular_reflectance':{'type':'rgb','value':[0.8,0.9,1.0]}}, d(0.6,0.4), d(0.5,3.9)),
 ({'type':'pplastic','distribution':'beckmann','alpha_u':0.1,'alpha_v':0.3,'eta':1.33,'sample_visible':False}, d(0.7,0.3), d(0.4,3.0)),
]
for p,wi,wo in pcases:
    b=mi.load_dict(p)
    si=mi.SurfaceInteraction3f(); si.wi=wi; si.sh_frame=mi.Frame3f(mi.Vector3f(0,0,1)); si.n=mi.Vector3f(0,0,1)
    v=b.eval(ctx,si,wo); pdf=b.pdf(ctx,si,wo)
    print(p, [float(x) for x in wi], [float(x) for x in wo], 'eval', ['%.10g' % float(x) for x in v], 'pdf', '%.10g' % float(pdf))
for p in [{'type':'polarizer'}, {'type':'polarizer','theta':30.0,'transmittance':{'type':'rgb','value':[0.8,0.5,0.2]}}]:
    b=mi.load_dict(p)
    si=mi.SurfaceInteraction3f(); si.wi=d(0.6,0.5); si.sh_frame=mi.Frame3f(mi.Vector3f(0,0,1)); si.n=mi.Vector3f(0,0,1)
    bs,w=b.sample(ctx,si,0.3,mi.Point2f(0.2,0.7))
    print(p, 'wo', [float(x) for x in bs.wo], 'weight', [float(x) for x in w], 'eval', [float(x) for x in b.eval(ctx,si,-si.wi)],
          'null transmission', [float(x) for x in b.eval_null_transmission(si)])
