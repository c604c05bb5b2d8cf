#!/usr/bin/env python3
"""Real-scene corpus (issue 18): public Mitsuba 3 scenes written by other people, rendered unchanged.

For every scene file of the corpus it makes a small copy (film scaled to --res pixels wide, nothing
else changed; included files are copied the same way) and records
  load_path / load_rcache   rcache renders it in strict mode with --integrator path / rcache
                            (else the first error line: the first unsupported feature, file:line)
  lenient                   rcache --lenient renders it (and how many substitutions it listed)
  mitsuba                   Mitsuba 3 renders it (--variant, default llvm_ad_rgb: its scalar variants
                            weight samples with a 31-step table of the reconstruction filter, which
                            rcache and the JIT variants evaluate exactly; see bench/RESULTS.md, ninth
                            session, for the per-pixel difference at edges)
and, where both rcache's path tracer and Mitsuba render it, compares them (rcache with the file's own
integrator where it takes it, e.g. `direct`, else --integrator path — also for a file's path tracer,
which rcache's default `auto` would render with its radiance cache; compare_integrator says which;
--compare-integrator NAME compares that integrator instead, e.g. rcache against Mitsuba's path tracer):
  mean_ratio                per-channel mean(rcache, --seeds seeds) / mean(Mitsuba)
  block_z                   the largest |rcache − Mitsuba| of a 16-px block mean in units of its noise
                            (bench/agreement_stats.py: each renderer's seed scatter, pooled over
                            4×4-px sub-blocks per channel; the ratio is read as Student's t with the
                            pool's effective degrees of freedom and reported as the normal deviate
                            of the same tail probability)
  null_block_z              block_z of the last seed against the others: a check of the noise estimate
  agree                     |mean_ratio − 1| < 1 % in every channel and block_z < 4
One JSON line per scene, then a summary line.

The corpus is not shipped (sizes, licences); build it from the public repositories, e.g.
  git -C mitsuba-data archive ... (mitsuba-renderer/mitsuba-data: docs/scenes, scenes, common)
  mitsuba-renderer/mitsuba-tutorials: scenes/
into one folder (default /tmp/corpus, layout as in those repositories, tutorials under tutorials/).
Scenes that need mitsuba-data's Git-LFS assets missing from the snapshot fail in both renderers.

  DRJIT_LIBLLVM_PATH=... /root/.cache/rcache/bench-venv/bin/python bench/real_scenes.py \
      --rcache build/rcache --corpus /tmp/corpus --res 64 --spp 64 --spp-mitsuba 256 \\
      [--seeds 4 --seeds-mitsuba 4 --variant llvm_ad_rgb (the defaults)] [--resume] [--only NAME...]
      [--first-seed N] [--seed-per-scene]

Seeds: rcache renders seeds N … N+K−1 and Mitsuba N−1 … N+K'−2 (N = --first-seed, default 1: the
seeds of earlier runs). A rerun with another N draws fresh samples. --seed-per-scene adds to N a
stable offset drawn from the scene's path, so that a family of files sharing floor, envmap and camera
(the matpreview scenes) does not read one and the same draw: with fixed seeds their errors correlate
and a 4-seed fluctuation shows in every member at once. Image names carry the first seed, so --resume
keeps only references drawn with the same seeds.
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import zlib

import numpy as np

from agreement_stats import compare

# Scene files of the corpus (relative to --corpus). Fragments meant only for <include> are left out.
CORPUS_GLOBS = ["docs/scenes/*.xml", "docs/scenes/principled_blend_creation/*.xml", "scenes/*.xml",
                "scenes/cbox/*.xml", "scenes/matpreview/*.xml", "tutorials/scenes/*.xml",
                "tutorials/scenes/lego/*.xml"]

MITSUBA_SNIPPET = r"""
import sys, mitsuba as mi
mi.set_variant(sys.argv[4])
scene = mi.load_file(sys.argv[1])
for k in range(int(sys.argv[5])):
    mi.Bitmap(mi.render(scene, spp=int(sys.argv[3]), seed=int(sys.argv[6]) + k)).write(sys.argv[2] % k)
"""


def shrink_film(text, res):
    """Scales every <film>'s integer width/height to `res` pixels wide (aspect kept)."""
    def film(m):
        block = m.group(0)
        w = re.search(r'<integer\s+name="width"\s+value="(\d+)"\s*/>', block)
        h = re.search(r'<integer\s+name="height"\s+value="(\d+)"\s*/>', block)
        if not w or not h:
            return block
        W, H = int(w.group(1)), int(h.group(1))
        nh = max(1, round(res * H / W))
        block = block.replace(w.group(0), '<integer name="width" value="%d"/>' % res)
        return block.replace(h.group(0), '<integer name="height" value="%d"/>' % nh)
    return re.sub(r"<film\b.*?</film>", film, text, flags=re.S)


def make_copy(corpus, work, res):
    """Hard-linked copy of the corpus with every .xml rewritten (unlinked first: the originals stay)."""
    if os.path.exists(work):
        shutil.rmtree(work)
    shutil.copytree(corpus, work, copy_function=os.link)
    for path in glob.glob(os.path.join(work, "**", "*.xml"), recursive=True):
        with open(path, errors="replace") as f:
            text = f.read()
        os.unlink(path)
        with open(path, "w") as f:
            f.write(shrink_film(text, res))


def run(cmd, timeout):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        return -1, "timeout after %d s" % timeout


def first_error(text):
    for line in text.splitlines():
        if "error" in line.lower() or ": " in line:
            return line.strip()[:300]
    return text.strip()[:300]


def first_seed_of(rel, args):
    """--first-seed, plus a stable per-scene offset (a multiple of 1000, so runs with nearby --first-seed
    values never share seeds) where --seed-per-scene asks for one."""
    offset = 1000 * (zlib.crc32(rel.encode()) % 100000) if args.seed_per_scene else 0
    return args.first_seed + offset


def timeout_for(rel, args):
    """--timeout, or the first --timeout-for PATTERN=SECONDS whose pattern is a substring of the path."""
    for item in args.timeout_for or []:
        pattern, seconds = item.rsplit("=", 1)
        if pattern in rel:
            return int(seconds)
    return args.timeout


def load_exr(path):
    import mitsuba as mi
    return np.array(mi.Bitmap(path), dtype=np.float64)[..., :3]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rcache", default="build/rcache")
    ap.add_argument("--corpus", default="/tmp/corpus")
    ap.add_argument("--work", default="/tmp/rcache_real_scenes")
    ap.add_argument("--res", type=int, default=64)
    ap.add_argument("--spp", type=int, default=64, help="rcache path tracer spp per seed")
    ap.add_argument("--seeds", type=int, default=4, help="rcache seeds (≥ 2; their scatter is the noise estimate)")
    ap.add_argument("--spp-mitsuba", type=int, default=256)
    ap.add_argument("--seeds-mitsuba", type=int, default=4,
                    help="Mitsuba seeds sharing --spp-mitsuba (≥ 2: their scatter is Mitsuba's noise)")
    ap.add_argument("--variant", default="llvm_ad_rgb", help="Mitsuba variant of the reference")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--timeout", type=int, default=300)
    ap.add_argument("--timeout-for", nargs="*", metavar="PATTERN=SECONDS",
                    help="a shorter (or longer) limit for scenes whose path contains PATTERN")
    ap.add_argument("--first-seed", type=int, default=1, help="rcache's first seed (Mitsuba's is one less)")
    ap.add_argument("--seed-per-scene", action="store_true",
                    help="offset the first seed by a stable hash of the scene's path")
    ap.add_argument("--no-mitsuba", action="store_true")
    ap.add_argument("--resume", action="store_true", help="keep Mitsuba references already in --work")
    ap.add_argument("--compare-only", action="store_true",
                    help="only the comparison, for scenes whose Mitsuba references --work already holds (no load, "
                         "lenient or Mitsuba runs): e.g. --compare-integrator rcache after a run of the path tracer")
    ap.add_argument("--only", nargs="*", help="substrings of scene paths to run")
    ap.add_argument("--compare-integrator", help="compare this integrator (e.g. path, rcache) instead of the file's")
    args = ap.parse_args()
    rcache = os.path.abspath(args.rcache)
    copy = os.path.join(args.work, "corpus")
    out = os.path.join(args.work, "images")
    make_copy(args.corpus, copy, args.res)
    os.makedirs(out, exist_ok=True)

    scenes = []
    for g in CORPUS_GLOBS:
        scenes += sorted(os.path.relpath(p, copy) for p in glob.glob(os.path.join(copy, g)))
    if args.only:
        scenes = [s for s in scenes if any(o in s for o in args.only)]
    totals = {"scenes": 0, "load_path": 0, "load_rcache": 0, "lenient": 0, "mitsuba": 0, "compared": 0, "agree": 0}
    for rel in scenes:
        path = os.path.join(copy, rel)
        tag = rel.replace("/", "_")[:-4]
        first = first_seed_of(rel, args)
        timeout = timeout_for(rel, args)
        row = {"scene": rel, "first_seed": first}
        base = [rcache, path, "-t", str(args.threads), "--quiet"]
        for integ in ("path", "rcache") if not args.compare_only else ():
            rc, text = run(base + ["--integrator", integ, "--spp", "4", "-o", os.path.join(out, tag + "_" + integ + "_4.exr")],
                           timeout)
            row["load_" + integ] = rc == 0 or first_error(text)
        if not args.compare_only:
            rc, text = run(base + ["--lenient", "--integrator", "path", "--spp", "4", "-o", os.path.join(out, tag + "_lenient.exr")],
                           timeout)
            row["lenient"] = rc == 0 or first_error(text)
        loads = row.get("load_path", True) is True  # (not checked with --compare-only: the earlier run's)
        if args.compare_only and not all(os.path.exists(os.path.join(out, "%s_mitsuba_f%d_s%d.exr" % (tag, first - 1, k)))
                                         for k in range(args.seeds_mitsuba)):
            row["mitsuba"] = "no kept reference"
        elif not args.no_mitsuba:
            # Whether Mitsuba renders it at all (4 spp), then a reference only where rcache renders too.
            ref = os.path.join(out, "%s_mitsuba_f%d_s%%d.exr" % (tag, first - 1))
            refs = [ref % k for k in range(args.seeds_mitsuba)]
            kept = (args.resume or args.compare_only) and all(os.path.exists(r) for r in refs)
            rc, text = (0, "") if kept else run([sys.executable, "-c", MITSUBA_SNIPPET, path, ref, "4", args.variant, "1", str(first - 1)],
                                                timeout)
            row["mitsuba"] = rc == 0 or first_error(text.strip().splitlines()[-1] if text.strip() else text)
            if row["mitsuba"] is True and loads and not kept:
                rc, text = run([sys.executable, "-c", MITSUBA_SNIPPET, path, ref, str(args.spp_mitsuba // args.seeds_mitsuba),
                                args.variant, str(args.seeds_mitsuba), str(first - 1)], timeout * 4)
                row["mitsuba"] = rc == 0 or first_error(text)
            if row["mitsuba"] is True and loads:
                # The file's own integrator where rcache takes it (a `direct` file must be compared as
                # direct illumination, not as the path tracer --integrator path would make of it), else
                # the path tracer — also where the file asks for a path tracer, which rcache's `auto`
                # would turn into its radiance cache (an approximation, not the estimator Mitsuba runs).
                probe_stats = os.path.join(out, tag + "_auto_stats.json")
                rc, text = (1, "") if args.compare_integrator else run(
                    base + ["--spp", "1", "-o", os.path.join(out, tag + "_auto_1.exr"), "--stats", probe_stats], timeout)
                # (The statistics name the estimator: a `direct` file runs as "path" with its own
                # parameters, which --integrator path would drop.)
                auto, volumetric = None, False
                if rc == 0:
                    with open(probe_stats) as f:
                        probe = json.load(f)
                    auto = probe.get("integrator")
                    # A file whose volpath follows media (rcache's path_core says so) is compared as
                    # volpath: Mitsuba's `path` ignores media, so --integrator path would too.
                    volumetric = probe.get("path_core", "").startswith("volpath")
                forced = auto is None or auto == "rcache"
                imgs = []
                if args.compare_integrator:
                    forced, chosen = True, args.compare_integrator
                else:
                    chosen = ("volpath" if volumetric else "path") if forced else None
                for seed in range(first, first + args.seeds):
                    img = os.path.join(out, "%s_%s_s%d.exr" % (tag, chosen or "own", seed))
                    flags = ["--spp", str(args.spp), "--seed", str(seed), "-o", img]
                    rc, text = run(base + (["--integrator", chosen] if forced else []) + flags, timeout)
                    imgs.append(img if rc == 0 else None)
                row["compare_integrator"] = chosen if forced else "file's (%s)" % auto
                if all(imgs):
                    seeds, mseeds = [load_exr(i) for i in imgs], [load_exr(r) for r in refs]
                    if seeds[0].shape == mseeds[0].shape:
                        row["mean_ratio"], row["block_z"], row["mean_z"] = compare(seeds, mseeds, args.spp, args.spp_mitsuba)
                        # The same statistic between rcache's own seeds (the last one as the reference):
                        # agreement by construction, so beyond 4 only as often as a normal 4σ.
                        row["null_block_z"] = compare(seeds[:-1], seeds[-1:], args.spp, args.spp)[1] if len(seeds) > 2 else None
                        row["agree"] = bool(all(abs(r - 1) < 0.01 for r in row["mean_ratio"]) and
                                            (row["block_z"] is None or row["block_z"] < 4))
                    else:
                        row["agree"] = False
                        row["shape_mismatch"] = [list(seeds[0].shape), list(mseeds[0].shape)]
        print(json.dumps(row), flush=True)
        totals["scenes"] += 1
        for k in ("load_path", "load_rcache", "lenient", "mitsuba"):
            totals[k] += row.get(k) is True
        totals["compared"] += "agree" in row
        totals["agree"] += row.get("agree") is True
    print(json.dumps({"summary": totals}), flush=True)


if __name__ == "__main__":
    main()
