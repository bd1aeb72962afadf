#!/usr/bin/python3
"""Chart of `rtsim speed-vs-error`.

Usage: speed_error_chart.py SPEED_VS_ERROR.json OUTDIR  -- writes OUTDIR/speed_vs_error.png.
Left: cycle error (with the sampled level's 95% interval) against speed-up, the goal region
shaded. Right: each level's error in DRAM bytes (%) and hit rates (percentage points).
"""
import json
import os
import sys

import chart_style


def main(path, outdir):
    doc = json.load(open(path))
    goal = doc["goal"]
    rows = [r for r in doc["rows"] if r["label"] != doc["reference"]["label"]]
    fig, (left, right) = chart_style.new(11, 4, ncols=2)
    for r in rows:
        c = r["cycles"]
        if c is None:
            continue
        err = 100 * c["error"]
        ci = 100 * c["ci95"] / c["value"] if c["value"] else 0
        left.errorbar(r["speedup"], err, yerr=ci, fmt="o", capsize=3, label=r["label"])
        left.annotate(r["label"], (r["speedup"], err), textcoords="offset points",
                      xytext=(4, 4), fontsize=7)
    g = 100 * goal["max_cycle_error"]
    left.axhspan(-g, g, color="#55a868", alpha=0.12, label="goal: error <= %g%%" % g)
    left.axvline(goal["min_speedup"], color="#55a868", ls="--", lw=1,
                 label="goal: speed-up >= %gx" % goal["min_speedup"])
    left.axhline(0, color="black", lw=0.6)
    left.set_xscale("log")
    left.set_xlabel("speed-up against the full cycle model (CPU time)")
    left.set_ylabel("cycle error (%)")
    left.set_title("cycles: error against speed-up")
    left.legend(fontsize=7, loc="best")
    metrics = [("dram_bytes", "DRAM bytes (%)", 100), ("l1_hit_rate", "L1 hit rate (pp)", 100),
               ("l2_hit_rate", "L2 hit rate (pp)", 100)]
    width = 0.8 / len(metrics)
    for k, (key, name, scale) in enumerate(metrics):
        xs, ys = [], []
        for i, r in enumerate(rows):
            if r[key] is not None:
                xs.append(i + (k - 1) * width)
                ys.append(scale * r[key]["error"])
        right.bar(xs, ys, width, label=name)
    right.axhline(0, color="black", lw=0.6)
    right.set_xticks(range(len(rows)))
    right.set_xticklabels([r["label"] for r in rows], rotation=30, ha="right", fontsize=7)
    right.set_ylabel("error")
    right.set_title("memory: error against the full model")
    right.legend(fontsize=7)
    ctx = doc["context"]
    fig.suptitle("%s on %s: %d rays" % (ctx["workload"], ctx["config"], ctx["rays"]))
    chart_style.save(fig, os.path.join(outdir, "speed_vs_error.png"))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
