#!/usr/bin/env python3
"""bench/agreement_stats.py: Student's t tails against closed forms, and the block z of images that
agree by construction (noise in a few sub-blocks only) beyond 4 no more often than a normal 4σ."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench"))
import agreement_stats as st  # noqa: E402

failures = 0


def check(name, ok, detail=""):
    global failures
    print(("ok   " if ok else "FAIL ") + name + (" " + detail if detail else ""))
    failures += not ok


# t(1) is Cauchy: P(|T| > t) = 1 − 2·atan(t)/π; t(2): 1 − t/√(2 + t²).
for t in (0.3, 1.0, 4.0, 30.0):
    check("t1 tail %g" % t, abs(st.t_two_sided_tail(t, 1) - (1 - 2 * math.atan(t) / math.pi)) < 1e-10)
    check("t2 tail %g" % t, abs(st.t_two_sided_tail(t, 2) - (1 - t / math.sqrt(2 + t * t))) < 1e-10)
# Many degrees of freedom: the normal law (P(|Z| > 4) = erfc(4/√2)).
check("t1e7 tail 4", abs(st.t_two_sided_tail(4.0, 1e7) / math.erfc(4 / math.sqrt(2)) - 1) < 1e-4)
check("normal equivalent of t(1e7)", abs(st.normal_equivalent(3.0, 1e7) - 3.0) < 1e-4)
# t(2) at 4: tail 1 − 4/√18 = 0.0572, i.e. a normal 1.90σ.
check("normal equivalent of t(2)", abs(st.normal_equivalent(4.0, 2) - 1.9022) < 1e-3, str(st.normal_equivalent(4.0, 2)))

# Images that agree: per block, 2 of its 16 sub-blocks carry all the noise (an emitter's edge); K
# rcache seeds at 64 spp and Mitsuba at 256. 600 blocks × 3 channels.
rng = np.random.default_rng(7)
nb = 600
shape = (16, 16 * nb, 3)
mask = np.zeros(shape)
for b in range(nb):
    for k in rng.choice(16, 2, replace=False):
        y, x = 4 * (k // 4), 16 * b + 4 * (k % 4)
        mask[y:y + 4, x:x + 4] = 1.0
truth = 1.0
m = truth + mask * rng.normal(0, 0.5, shape)  # 4× the samples: half the σ
for K in (2, 4):
    seeds = [truth + mask * rng.normal(0, 1, shape) for _ in range(K)]
    z = st.block_z(seeds, [m], 64, 256)
    beyond = int((z > 4).sum())
    # A normal variable is beyond 4σ with probability 6.3e-5 (≈0.1 of 1800); the ratio to the pooled
    # σ without the t correction (ν_eff ≈ 2(K−1)) is beyond 4 5.7 % (K = 2) or 0.7 % (K = 4) of the time.
    check("K=%d: agreeing blocks beyond 4: %d of %d" % (K, beyond, z.size), beyond <= 3)
# A reference noisier per sample than rcache (e.g. fireflies rcache's sampling avoids): its own seeds'
# scatter measures it (the single-image reading would assume rcache's variance for it).
mseeds = [truth + mask * rng.normal(0, 3, shape) for _ in range(4)]  # 4 seeds × 64 spp, σ 3× rcache's
z = st.block_z(seeds, mseeds, 64, 256)
check("Mitsuba seeds: agreeing blocks beyond 4: %d of %d" % (int((z > 4).sum()), z.size), int((z > 4).sum()) <= 3)
# A real difference stays visible with 4 seeds (ν_eff ≈ 6): a shift of 0.3 against a block σ of
# √(2·(1/16)/256 · (1/4 + 1/4)) = 0.016 (t ≈ 19).
moved = st.block_z([s + 0.3 for s in seeds], [m], 64, 256)
check("a shifted image is found", float(np.median(moved)) > 4, "median z %.1f" % float(np.median(moved)))
sys.exit(1 if failures else 0)
