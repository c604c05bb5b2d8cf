"""Plot of walk_results.json (run with the bench venv's python, which has matplotlib):
time per frame of the three renderings, and flicker / error over the still frames."""
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
r = json.load(open(os.path.join(HERE, "walk_results.json")))
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "walk_time_flicker.png")
fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.6))
labels = {"shared": "rcache, shared cache", "fresh": "rcache, every frame from scratch",
          "path": "path tracer, %d spp (equal time)" % r["path"]["spp"]}
for k in ("shared", "fresh", "path"):
    a.plot(r[k]["time_per_frame_s"], label=labels[k], marker=".")
a.axvline(r["still_from"], color="grey", lw=0.5)
a.set_xlabel("frame (camera still from frame %d)" % r["still_from"])
a.set_ylabel("time per frame [s]")
a.legend(fontsize=7)
keys = ["shared", "fresh", "path"]
x = range(len(keys))
b.bar([i - 0.2 for i in x], [r[k]["flicker"] for k in keys], width=0.4, label="temporal flicker (std/mean)")
b.bar([i + 0.2 for i in x], [10 * r[k]["relmse_still"] for k in keys], width=0.4, label="10 × relMSE vs reference")
b.set_xticks(list(x))
b.set_xticklabels(["shared", "from scratch", "path"])
b.legend(fontsize=7)
fig.suptitle("24-frame walk-through, glossy Cornell box %d², 2 cores (shared machine)" % r["res"], fontsize=9)
fig.tight_layout()
fig.savefig(out, dpi=100)
