#!/usr/bin/python3
"""Chart of `rtsim curve`.

Usage: curve_chart.py OUTDIR CURVE.json  -- writes OUTDIR/curve.png.
Left: DRAM bytes per ray (bytes below the level, for a level above another) against the curved
level's capacity (log axis), one line per associativity, the 95%
interval when sampled, the knee marked, and the full model's DRAM bytes where it ran. Right:
cycles where known: simulated points filled, interpolated and extrapolated ones hollow.
       curve_chart.py OUTDIR CURVE.json CURVE.json...  -- the curves of several L1 sizes
(`rtsim curve --l1`): OUTDIR/curve-l1.png, DRAM bytes per ray and cycles against the curved
level's capacity, one line per first-level size (the first associativity), knees marked.
"""
import json
import os
import sys

import chart_style


def below_label(doc):
    """What dram_bytes_per_ray is: DRAM's bytes for the last level, else the level below's."""
    ctx = doc["context"]
    return "DRAM bytes per ray" if ctx["above_dram"] else "bytes per ray below %s" % ctx["level"]


def main(path, outdir):
    doc = json.load(open(path))
    fig, (left, right) = chart_style.new(11, 4, ncols=2)
    ways = sorted({p["ways"] for p in doc["points"]})
    for w in ways:
        pts = sorted((p for p in doc["points"] if p["ways"] == w), key=lambda p: p["capacity_bytes"])
        x = [p["capacity_bytes"] for p in pts]
        y = [p["dram_bytes_per_ray"] for p in pts]
        ci = [p["dram_bytes_per_ray_ci95"] for p in pts]
        line = left.errorbar(x, y, yerr=ci if any(ci) else None, marker="o", ms=4, capsize=3,
                             label="curve, %d ways" % w)
        for p in pts:
            if p["knee"]:
                left.annotate("knee", (p["capacity_bytes"], p["dram_bytes_per_ray"]),
                              textcoords="offset points", xytext=(6, 8), fontsize=8,
                              arrowprops={"arrowstyle": "->", "lw": 0.8})
        runs = [p for p in pts if p["cycle_run"]]
        if runs:
            left.plot([p["capacity_bytes"] for p in runs],
                      [p["cycle_run"]["dram_bytes_per_ray"] for p in runs], "x", ms=8,
                      color=line[0].get_color(), label="full model, %d ways" % w)
        known = [p for p in pts if p["cycles"] is not None]
        for kind, style in (("simulated", "o"), ("interpolated", "o"), ("extrapolated", "s")):
            sel = [p for p in known if p["cycles_from"] == kind]
            if sel:
                right.plot([p["capacity_bytes"] for p in sel], [p["cycles"] for p in sel],
                           style, ms=6, label="%s, %d ways" % (kind, w),
                           fillstyle="full" if kind == "simulated" else "none")
        if known:
            right.plot([p["capacity_bytes"] for p in known], [p["cycles"] for p in known],
                       "-", lw=0.8, color="#777777")
    level = doc["context"]["level"]
    for ax in (left, right):
        ax.set_xscale("log", base=2)
        chart_style.size_axis(ax)
        ax.set_xlabel("%s capacity (bytes)" % level)
    left.set_ylabel(below_label(doc))
    left.set_title("%s (%s)" % (below_label(doc), doc["method"]))
    left.legend(fontsize=7)
    right.set_ylabel("cycles")
    right.set_title("cycles: full model where simulated, else interpolated")
    if right.lines:
        right.legend(fontsize=7)
    ctx = doc["context"]
    fig.suptitle("%s on %s: %d rays" % (os.path.basename(ctx["stream"]), ctx["config"],
                                         ctx["rays"]))
    chart_style.save(fig, os.path.join(outdir, "curve.png"))


def family(outdir, paths):
    docs = [json.load(open(p)) for p in paths]
    fig, (left, right) = chart_style.new(11, 4, ncols=2)
    for doc in docs:
        first = doc["points"][0]["ways"]
        pts = sorted((p for p in doc["points"] if p["ways"] == first),
                     key=lambda p: p["capacity_bytes"])
        label = "%s %s" % (doc["context"]["first_level"],
                           chart_style.size_text(doc["context"]["first_level_bytes"]))
        x = [p["capacity_bytes"] for p in pts]
        line = left.plot(x, [p["dram_bytes_per_ray"] for p in pts], "o-", ms=4, label=label)
        for p in pts:
            if p["knee"]:
                left.plot(p["capacity_bytes"], p["dram_bytes_per_ray"], "*", ms=12,
                          color=line[0].get_color())
        known = [p for p in pts if p["cycles"] is not None]
        if known:
            right.plot([p["capacity_bytes"] for p in known], [p["cycles"] for p in known],
                       "o-", ms=4, color=line[0].get_color(), label=label)
    ctx = docs[0]["context"]
    for ax in (left, right):
        ax.set_xscale("log", base=2)
        chart_style.size_axis(ax)
        ax.set_xlabel("%s capacity (bytes)" % ctx["level"])
    left.set_ylabel(below_label(docs[0]))
    left.set_title("%s by %s size (stars: knees)" % (below_label(docs[0]), ctx["first_level"]))
    left.legend(fontsize=7)
    right.set_ylabel("cycles")
    right.set_title("cycles: simulated or interpolated")
    if right.lines:
        right.legend(fontsize=7)
    ctx = docs[0]["context"]
    fig.suptitle("%s on %s: %d rays" % (os.path.basename(ctx["stream"]), ctx["config"],
                                         ctx["rays"]))
    chart_style.save(fig, os.path.join(outdir, "curve-l1.png"))


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    if len(sys.argv) == 3:
        main(sys.argv[2], sys.argv[1])
    else:
        family(sys.argv[1], sys.argv[2:])
