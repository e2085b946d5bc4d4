#!/usr/bin/env python3
"""Plots docs/data/build_bench.json: build time against N for the SAH kd-tree and the SAH BVH,
with c N log2 N fitted through the largest point of each, into docs/images/build-scaling.png.
Sizes built five times are plotted at their median, with the fastest and slowest as a bar."""
import json
import math
import pathlib

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

ROOT = pathlib.Path(__file__).resolve().parent.parent
data = json.loads((ROOT / "docs/data/build_bench.json").read_text())

# A size built once gives one row; one built five times gives aggregates: its median is the
# point, its min and max the error bar.
series = {}
spread = {}
for b in data["benchmarks"]:
    name = b["name"].split("/")[0]
    if not name.endswith("Build"):
        continue
    ms = b["real_time"] if b["time_unit"] == "ms" else b["real_time"] / 1e6
    kind = b.get("aggregate_name") if b.get("run_type") == "aggregate" else "one"
    if kind in ("one", "median"):
        series.setdefault(name, []).append((b["N"], ms))
    elif kind in ("min", "max"):
        spread.setdefault((name, b["N"]), {})[kind] = ms

fig, ax = plt.subplots(figsize=(6.4, 4.2))
labels = {"BM_KdTreeSahBuild": "kd-tree, SAH exact (sorted split events, Wald & Havran)",
          "BM_KdTreeFastBuild": "kd-tree, SAH fast (16-32 bins, float references, 2 threads)",
          "BM_BvhSahBuild": "BVH, binned SAH"}
for name, pts in series.items():
    pts.sort()
    n = [p[0] for p in pts]
    t = [p[1] for p in pts]
    line, = ax.loglog(n, t, "o-", label=labels.get(name, name))
    bars = [spread.get((name, x)) for x in n]
    if all(bars):
        ax.errorbar(n, t, yerr=[[m - b["min"] for m, b in zip(t, bars)],
                                [b["max"] - m for m, b in zip(t, bars)]],
                    fmt="none", ecolor=line.get_color(), capsize=2)
    c = t[-1] / (n[-1] * math.log2(n[-1]))
    ax.loglog(n, [c * x * math.log2(x) for x in n], "--", color=line.get_color(), alpha=0.5,
              label="c N log N through the last point")
ax.set_xlabel("triangles N")
ax.set_ylabel("build time (ms, wall clock)")
ax.set_title("Build time against N (torus-knot tube meshes)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
out = ROOT / "docs/images/build-scaling.png"
fig.savefig(out, dpi=110)
print("wrote", out)
