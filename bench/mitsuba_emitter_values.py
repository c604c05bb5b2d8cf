"""Mitsuba 3.9.1 scalar_rgb Emitter.sample_direction values of projector and textured-spot configurations:
the reference values of tests/render/spot_light_test.cpp (ProjectorLight.*, SpotLight.ProjectedTextureMatchesMitsuba).
  /root/.cache/rcache/bench-venv/bin/python bench/mitsuba_emitter_values.py
"""
import mitsuba as mi
mi.set_variant('scalar_rgb')
T = mi.ScalarTransform4f
cases = {
 'projector_const': {'type':'projector','fov':32.0,'irradiance':{'type':'rgb','value':[25.5,38.0,20.1]},
    'to_world': T().look_at(origin=[4,0,5.5], target=[0,0,1], up=[-1,0,0])},
 'projector_checker': {'type':'projector','fov':40.0,'fov_axis':'y','scale':2.5,
    'irradiance':{'type':'checkerboard','color0':{'type':'rgb','value':[0.9,0.5,0.1]},'color1':{'type':'rgb','value':[0.1,0.2,0.7]},
                  'to_uv': mi.ScalarTransform4f().scale([4,4,1])},
    'to_world': T().look_at(origin=[0,0,3], target=[0.2,0.1,0], up=[0,1,0])},
 'spot_checker': {'type':'spot','cutoff_angle':30.0,'intensity':{'type':'rgb','value':[50,40,30]},
    'texture':{'type':'checkerboard','color0':{'type':'rgb','value':[0.9,0.5,0.1]},'color1':{'type':'rgb','value':[0.1,0.2,0.7]},
                  'to_uv': mi.ScalarTransform4f().scale([4,4,1])},
    'to_world': T().look_at(origin=[0,0,3], target=[0.2,0.1,0], up=[0,1,0])},
}
pts = [[0.3,0.2,1.0],[-0.5,0.4,0.0],[0.1,-0.6,0.5],[0.9,0.9,0.0],[1.2,-0.3,1.1]]
for name, d in cases.items():
    e = mi.load_dict(d)
    for p in pts:
        it = mi.Interaction3f(); it.p = mi.Point3f(p); it.t=0; it.wavelengths=[]
        ds, w = e.sample_direction(it, mi.Point2f(0.5,0.5))
        print(name, p, ['%.9g' % float(x) for x in w])
