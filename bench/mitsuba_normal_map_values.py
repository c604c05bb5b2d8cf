#!/usr/bin/env python3
"""normalmap / bumpmap against Mitsuba 3 (scalar_rgb): a 10x10 rectangle under a directional light
seen from above, diffuse 0.5 inside (1) a constant normal map tilted 30 deg toward dp/du, with and
without the shadowing function, and (2) a bumpmap over a 4x1 grey ramp (clamp, bilinear), scale 0.5,
where the closed form is known: n ~ (-s*dh/du*|dp/dv|, 0, |dp/du||dp/dv|) with dh/du = 1 per unit u.

Prints, per case, Mitsuba's image mean, the closed form, and (with --rcache BIN) rcache's path
tracer on the same file. Usage: bench/mitsuba_normal_map_values.py [--rcache build/rcache]
"""
import argparse, math, os, subprocess, sys, tempfile

import numpy as np

TILT = math.radians(30.0)
TO_LIGHT = np.array([0.5, 0.2, 1.0]) / np.linalg.norm([0.5, 0.2, 1.0])


def tan2(c):
    return (1.0 - c * c) / (c * c)


def shadowing(cos_tilt, cos_light):
    a2 = min(0.125 * tan2(cos_tilt), 1.0)
    return 2.0 / (1.0 + math.sqrt(1.0 + a2 * tan2(cos_light)))


def scene(bsdf, spp):
    d = -TO_LIGHT
    return f"""<scene version="3.0.0">
<integrator type="path"><integer name="max_depth" value="2"/></integrator>
<sensor type="perspective"><float name="fov" value="20"/>
 <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
 <sampler type="independent"><integer name="sample_count" value="{spp}"/></sampler>
 <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/><rfilter type="box"/></film></sensor>
<shape type="rectangle"><transform name="to_world"><scale value="5"/></transform>{bsdf}</shape>
<emitter type="directional"><vector name="direction" value="{d[0]}, {d[1]}, {d[2]}"/><rgb name="irradiance" value="3"/></emitter>
</scene>
"""


def cases(tmp):
    n = np.array([math.sin(TILT), 0.0, math.cos(TILT)])
    c = 0.5 * (n + 1.0)
    diffuse = '<bsdf type="diffuse"><rgb name="reflectance" value="0.5"/></bsdf>'
    for shadow in (False, True):
        bsdf = (f'<bsdf type="normalmap"><boolean name="use_shadowing_function" value="{str(shadow).lower()}"/>'
                f'<rgb name="normalmap" value="{c[0]}, {c[1]}, {c[2]}"/>{diffuse}</bsdf>')
        g = shadowing(n[2], TO_LIGHT[2]) if shadow else 1.0
        yield f"normalmap tilt 30 shadowing={shadow}", bsdf, 0.5 / math.pi * 3.0 * float(n @ TO_LIGHT) * g
    # The ramp as a 4x1 EXR written with Mitsuba's own Bitmap.
    import mitsuba as mi
    ramp = os.path.join(tmp, "ramp.exr")
    mi.Bitmap(np.array([[0.0, 0.25, 0.5, 0.75]], dtype=np.float32).reshape(1, 4, 1)).write(ramp)
    s = 0.5
    # The rectangle scaled 5: |dp/du| = |dp/dv| = 10; dh/du = 1 on the ramp's interior (u in [1/8, 7/8]).
    nb = np.array([-s * 10.0, 0.0, 100.0]) / np.linalg.norm([-s * 10.0, 0.0, 100.0])
    bsdf = (f'<bsdf type="bumpmap"><boolean name="use_shadowing_function" value="false"/><float name="scale" value="{s}"/>'
            f'<texture type="bitmap" name="height"><string name="filename" value="{ramp}"/><boolean name="raw" value="true"/>'
            f'<string name="wrap_mode" value="clamp"/></texture>{diffuse}</bsdf>')
    yield "bumpmap ramp scale 0.5", bsdf, 0.5 / math.pi * 3.0 * float(nb @ TO_LIGHT)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rcache", help="rcache binary: also render its path tracer")
    args = ap.parse_args()
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    with tempfile.TemporaryDirectory() as tmp:
        for name, bsdf, expected in cases(tmp):
            path = os.path.join(tmp, "scene.xml")
            with open(path, "w") as f:
                f.write(scene(bsdf, 4))
            img = np.array(mi.render(mi.load_file(path)))
            line = f"{name:36s} mitsuba {img[..., 1].mean():.6f}  closed form {expected:.6f}"
            if args.rcache:
                out = os.path.join(tmp, "rc.exr")
                subprocess.run([args.rcache, path, "--integrator", "path", "-o", out], check=True,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                rc = np.array(mi.Bitmap(out))
                line += f"  rcache {rc[..., 1].mean():.6f}"
            print(line)


if __name__ == "__main__":
    sys.exit(main())
