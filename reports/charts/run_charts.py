#!/usr/bin/python3
"""Heatmaps and charts of an `rtsim run` report.

Usage: run_charts.py REPORT.json RUN_DIR  -- draws every available heatmap and chart listed in
REPORT.json's "images" into RUN_DIR (their "file" paths). Heatmaps read the per-pixel buffers
(raw float32) named in "pixel_buffers". Exits 1 if any image failed, after drawing the others.
"""
import json
import os
import sys

import numpy as np
from matplotlib.colors import LogNorm

import chart_style

HEATMAP_UNITS = {"heatmap_cycles": ("cycles", "cycles"),
                 "heatmap_nodes": ("nodes", "nodes"),
                 "heatmap_dram_bytes": ("dram_bytes", "bytes")}


def heatmap(report, run_dir, image):
    buffers = report["pixel_buffers"]
    w, h = buffers["width"], buffers["height"]
    key, unit = HEATMAP_UNITS[image["id"]]
    data = np.fromfile(os.path.join(run_dir, buffers["files"][key]), dtype="<f4")
    data = data.reshape(h, w)
    positive = data[data > 0]
    fig, ax = chart_style.new(7.5, 7.5 * h / w + 0.8)
    ax.grid(False)
    if positive.size:
        masked = np.ma.masked_where(data <= 0, data)
        cmap = chart_style.plt.get_cmap("inferno").copy()
        cmap.set_bad("black")
        shown = ax.imshow(masked, cmap=cmap, interpolation="nearest",
                          norm=LogNorm(vmin=positive.min(), vmax=positive.max()))
        fig.colorbar(shown, ax=ax, label="%s per pixel (log scale)" % unit, shrink=0.8)
    ax.set_title("%s (total %.4g)" % (image["title"], float(data.sum())))
    ax.set_xticks([])
    ax.set_yticks([])
    return fig


def latency_chart(report, run_dir, image):
    hist = report["latency"]["histogram"]
    edges = np.array(hist["edges"])
    centers = np.sqrt(edges[:-1] * edges[1:])
    fig, ax = chart_style.new(8, 4)
    used = np.nonzero(np.sum([np.array(c) for c in hist["counts"].values()], axis=0))[0]
    if used.size:
        ax.set_xlim(edges[max(used[0] - 1, 0)], edges[min(used[-1] + 2, len(edges) - 1)])
    for name, counts in hist["counts"].items():
        counts = np.array(counts, dtype=float)
        if counts.sum() == 0:
            continue
        ax.plot(centers, counts / counts.sum(), label=name, color=chart_style.color(name))
        p50 = report["latency"]["by_type"][name]["p50"]
        ax.axvline(p50, color=chart_style.color(name), ls="--", lw=0.7)
    ax.set_xscale("log")
    ax.set_xlabel("latency (cycles, dispatch to retirement)")
    ax.set_ylabel("share of the type's rays per bin")
    ax.set_title(image["title"])
    ax.legend(fontsize=7)
    return fig


def hit_rate_chart(report, run_dir, image):
    rates = report["hit_rates"]
    names = list(rates["by_type"])
    x = np.arange(len(names))
    fig, ax = chart_style.new(8, 3.8)
    for k, (level, color) in enumerate([("l1", "#4c72b0"), ("l2", "#dd8452")]):
        values = [100 * rates["by_type"][n][level] for n in names]
        ax.bar(x + (k - 0.5) * 0.38, values, 0.38, label=level.upper(), color=color)
        if rates[level] is not None:
            ax.axhline(100 * rates[level], color=color, lw=1, ls=":")
    ax.set_xticks(x)
    ax.set_xticklabels(names, rotation=20, ha="right")
    ax.set_ylim(0, 105)
    ax.set_ylabel("hit rate (%)")
    ax.set_title(image["title"])
    ax.legend(fontsize=8)
    return fig


def time_chart(report, run_dir, image):
    time = report["time"]
    panels = 1 + (time["utilisation"] is not None) + (time["timeline"] is not None)
    fig, axes = chart_style.new(4.2 * panels, 3.8, ncols=panels)
    axes = np.atleast_1d(axes)
    share = time["ray_time_share"]
    names = list(share)
    axes[0].barh(names, [100 * share[n] for n in names],
                 color=[chart_style.color(n) for n in names])
    axes[0].invert_yaxis()
    axes[0].set_xlabel("share of ray-slot time (%)")
    axes[0].set_title("by ray type")
    k = 1
    if time["utilisation"] is not None:
        util = time["utilisation"]
        axes[k].bar(list(util), [100 * v for v in util.values()], color="#8172b2")
        axes[k].set_ylim(0, 100)
        axes[k].set_ylabel("busy (%)")
        axes[k].set_title("units, ports and buses")
        axes[k].set_xticks(range(len(util)))
        axes[k].set_xticklabels(list(util), rotation=30, ha="right")
        k += 1
    if time["timeline"] is not None:
        line = time["timeline"]
        bucket = line["bucket_cycles"]
        series = line["retired"]
        length = max(len(v) for v in series.values())
        x = np.arange(length) * bucket
        axes[k].stackplot(x, [np.array(series[n], dtype=float) / bucket for n in series],
                          labels=list(series), colors=[chart_style.color(n) for n in series])
        axes[k].set_xlabel("cycle")
        axes[k].set_ylabel("rays retired per cycle")
        axes[k].set_title("over time")
        axes[k].legend(fontsize=6, loc="upper right")
    fig.suptitle(image["title"])
    return fig


def energy_chart(report, run_dir, image):
    energy = report["energy"]
    rays = max(report["timing"]["rays"], 1)
    fig, axes = chart_style.new(9, 3.8, ncols=2)
    structures = energy["structures"]
    names = list(structures)
    dynamic = [structures[n]["dynamic_nj"] / rays for n in names]
    static = [structures[n]["static_nj"] / rays for n in names]
    axes[0].barh(names, dynamic, color="#4c72b0", label="dynamic")
    axes[0].barh(names, static, left=dynamic, color="#c9c9c9", label="static")
    axes[0].invert_yaxis()
    axes[0].set_xlabel("nJ per ray")
    axes[0].set_title("by structure (%.3g nJ/ray, %.4g MRays/J at %s)"
                      % (energy["nj_per_ray"], energy["mrays_per_joule"], energy["node"]))
    axes[0].legend(fontsize=7)
    types = energy["by_type"]
    axes[1].bar(list(types), [t["dynamic_nj_per_ray"] for t in types.values()],
                color=[chart_style.color(n) for n in types])
    axes[1].set_ylabel("dynamic nJ per ray")
    axes[1].set_title("by ray type")
    axes[1].set_xticks(range(len(types)))
    axes[1].set_xticklabels(list(types), rotation=30, ha="right")
    fig.suptitle(image["title"])
    return fig


DRAW = {"heatmap_cycles": heatmap, "heatmap_nodes": heatmap, "heatmap_dram_bytes": heatmap,
        "chart_latency": latency_chart, "chart_hit_rates": hit_rate_chart,
        "chart_time": time_chart, "chart_energy": energy_chart}


def main(report_path, run_dir):
    report = json.load(open(report_path))
    images = [i for i in report["images"] if i["available"] and i["id"] in DRAW]
    chart_style.draw_all(images, lambda image: DRAW[image["id"]](report, run_dir, image), run_dir)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
