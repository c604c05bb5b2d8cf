#!/usr/bin/env python3
"""How rcache's cost grows with the work: wall time, peak memory, records and rays of one scene as
the image size, the rays per record and the SH order grow (one knob at a time, others at their
base value). Prints one JSON line per render. Usage (after scripts/build.sh):

    python3 bench/scaling.py [--scene cornell_glossy] [--threads 2] [--out bench/out/scaling]
"""
import argparse
import json
import os

from run_bench import ROOT, render

BASE = {"res": "96", "spp": "2", "rays": "1024", "a": "0.4"}
KNOBS = [("res", ["64", "128", "192", "256"]), ("rays", ["256", "1024", "4096"]), ("order", ["4", "8", "12", "16"])]


def run(scene, defines, threads, out_dir, tag):
    """One rcache render through the benchmark driver's runner (wall time, peak RSS, stats)."""
    params = {k: v for k, v in defines.items() if k not in ("res", "spp")}
    wall, mem, s = render(scene, os.path.join(out_dir, tag + ".exr"), "rcache", int(defines["spp"]),
                          int(defines["res"]), threads, params, os.path.join(out_dir, tag + ".json"))
    return dict(wall_s=wall, peak_mib=mem, records=s.get("records"), rays=s.get("rays"),
                time_cache_fill_s=s.get("time_cache_fill_s"), time_final_pass_s=s.get("time_final_pass_s"),
                lookups=s.get("lookups"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scene", default="cornell_glossy")
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "out", "scaling"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    scene = os.path.join(ROOT, "scenes", args.scene + ".xml")
    for knob, values in KNOBS:
        for v in values:
            defines = dict(BASE, **{knob: v})
            rec = dict(scene=args.scene, knob=knob, value=v, defines=defines)
            rec.update(run(scene, defines, args.threads, args.out, "%s_%s" % (knob, v)))
            print(json.dumps(rec), flush=True)


if __name__ == "__main__":
    main()
