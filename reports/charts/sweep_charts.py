#!/usr/bin/python3
"""Charts of an `rtsim sweep`.

Usage: sweep_charts.py SWEEP.json OUTDIR  -- draws every available chart listed in SWEEP.json's
"charts" into OUTDIR (their "file" paths):
  curve:  a metric against a swept key, one line per value of the series key (and of any
          other swept key); a y of "type.*.NAME" draws NAME for every ray type. A categorical
          x key (a value that is not a number: "bvh.node_format") draws grouped bars instead,
          one bar per series value (and ray type) in each category.
  pareto: cycles against a cost (on-chip memory, area, energy per ray), every point, with
          each workload's Pareto front.
Exits 1 if any chart failed, after drawing the others.
"""
import json
import sys

from matplotlib.lines import Line2D
from matplotlib.patches import Patch

import chart_style

LINESTYLES = ["-", "--", ":", "-."]


def value_of(point, key):
    if key == "workload":
        return point["workload"]
    return point["values"].get(key)


def metric(point, name):
    return (point.get("metrics") or {}).get(name)


def shown(key, value):
    """A swept value as a legend shows it: sizes as 256K, 1M, 4M."""
    return chart_style.size_text(value) if is_size(key) and is_number(value) else value


def label(point, keys):
    """key=value for each key the point sets (a [[point]] may leave some at the config's)."""
    return ", ".join("%s=%s" % (k, shown(k, value_of(point, k))) for k in keys
                     if value_of(point, k) is not None)


def order(text):
    try:
        return (0, float(text), "")
    except ValueError:
        return (1, 0.0, text)


def groups(points, keys):
    out = {}
    for p in points:
        out.setdefault(tuple(str(value_of(p, k)) for k in keys), []).append(p)
    return out


def is_size(key):
    """A swept key in bytes (size_bytes, line_bytes, ...): its axis reads 256K, 1M, 4M."""
    return key.endswith("bytes")


def y_values(members, y):
    """A metric of each point as drawn: rates in percent (chart_style.percent_scale)."""
    factor = chart_style.percent_scale(y)[0]
    return [None if metric(p, y) is None else metric(p, y) * factor for p in members]


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def y_lines(chart, points):
    """(metric, ray type or None) of each line: one, or one per ray type for type.*.NAME."""
    if not chart["y"].startswith("type.*."):
        return [(chart["y"], None)]
    name = chart["y"][len("type.*."):]
    types = sorted({m.split(".")[1] for p in points for m in p["metrics"]
                    if m.startswith("type.") and m.endswith("." + name)})
    return [("type.%s.%s" % (t, name), t) for t in types]


HATCHES = ["", "//", "..", "xx"]


def bars(doc, chart, points, others):
    """Grouped bars over a categorical x: a group per category, a bar per series and ray type."""
    x_key = chart["x"]
    categories = sorted({str(value_of(p, x_key)) for p in points}, key=order)
    ys = y_lines(chart, points)
    grouped = sorted(groups(points, others).items(), key=lambda kv: [order(v) for v in kv[0]])
    bars_drawn = [(g, members, y, ray_type) for g, (_, members) in enumerate(grouped)
                  for y, ray_type in ys if any(metric(p, y) is not None for p in members)]
    fig, ax = chart_style.new(9.5, 4.2)
    width = 0.8 / max(len(bars_drawn), 1)
    legend = []
    for i, (g, members, y, ray_type) in enumerate(bars_drawn):
        by_category = dict(zip([str(value_of(p, x_key)) for p in members], y_values(members, y)))
        heights = [by_category.get(c) for c in categories]
        xs = [c + (i - (len(bars_drawn) - 1) / 2) * width for c in range(len(categories))]
        heights = [float("nan") if h is None else h for h in heights]
        if ray_type is None:
            ax.bar(xs, heights, width, label=label(members[0], others))
            continue
        ax.bar(xs, heights, width, color=chart_style.color(ray_type), edgecolor="black",
               linewidth=0.3, hatch=HATCHES[g % len(HATCHES)], label=ray_type if g == 0 else None)
        if ray_type == ys[0][1]:
            legend.append(Patch(facecolor="white", edgecolor="black",
                                hatch=HATCHES[g % len(HATCHES)], label=label(members[0], others)))
    ax.set_xticks(range(len(categories)))
    ax.set_xticklabels([shown(x_key, float(c)) if is_size(x_key) and order(c)[0] == 0 else c
                        for c in categories])
    return finish(fig, ax, chart, x_key, legend)


def finish(fig, ax, chart, x_label, legend):
    """Axis labels, title and the legend (series, then the groups' entries) of a sweep chart."""
    ax.set_xlabel(x_label)
    ax.set_ylabel(chart["y"].replace("type.*.", "") + chart_style.percent_scale(chart["y"])[1])
    ax.set_title(chart["title"])
    handles, _ = ax.get_legend_handles_labels()
    ax.legend(handles=handles + legend, fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1))
    return fig


def curve(doc, chart):
    x_key, series = chart["x"], chart["series"]
    # A [[point]] list may leave the x key unset in some points: they have no place on the axis.
    points = [p for p in doc["points"] if p["metrics"] and value_of(p, x_key) is not None]
    others = [series] + [k for k in doc["spec"]["keys"] if k not in (x_key, series)]
    if not all(is_number(value_of(p, x_key)) for p in points):
        return bars(doc, chart, points, others)
    ys = y_lines(chart, points)
    fig, ax = chart_style.new(9.5, 4.2)
    legend = []
    grouped = sorted(groups(points, others).items(), key=lambda kv: [order(v) for v in kv[0]])
    for g, (key, members) in enumerate(grouped):
        members.sort(key=lambda p: value_of(p, x_key))
        xs = [value_of(p, x_key) for p in members]
        style = LINESTYLES[g % len(LINESTYLES)]
        for y, ray_type in ys:
            values = y_values(members, y)
            if all(v is None for v in values):
                continue
            if ray_type is None:
                ax.plot(xs, values, marker="o", ms=3, label=label(members[0], others))
                continue
            ax.plot(xs, values, marker="o", ms=3, ls=style, color=chart_style.color(ray_type),
                    label=ray_type if g == 0 else None)
        if ys[0][1] is not None:
            legend.append(Line2D([], [], color="black", ls=style, label=label(members[0], others)))
    log2_if_spread(ax, [value_of(p, x_key) for p in points])
    if is_size(x_key):
        chart_style.size_axis(ax)
    return finish(fig, ax, chart, x_key, legend)


def log2_if_spread(ax, xs):
    """A log2 x axis for values spread over 8x or more; linear otherwise (a log axis over
    less than an octave would have no tick)."""
    if xs and min(xs) > 0 and max(xs) / min(xs) >= 8:
        ax.set_xscale("log", base=2)


# Each cost a Pareto chart puts on x: its axis label and the scale from the metric's unit.
PARETO_X = {
    "on_chip_bytes": ("on-chip memory (bytes: L1s, L2, ray stacks, treelet ray buffer, sorting "
                      "buffer)", 1),
    "area_mm2": ("area on chip (mm²: test units, registers, SRAM; model/energy)", 1),
    "energy_nj_per_ray": ("energy per ray (nJ, dynamic and static; model/energy)", 1),
}


def pareto(doc, chart):
    x_label, scale = PARETO_X[chart["x"]]
    points = [p for p in doc["points"]
              if metric(p, "cycles") is not None and metric(p, chart["x"]) is not None]

    def cost(p):
        return metric(p, chart["x"]) * scale

    fig, ax = chart_style.new(8, 4.6)
    for w, members in sorted(groups(points, ["workload"]).items()):
        dots = ax.scatter([cost(p) for p in members], [metric(p, "cycles") for p in members],
                          s=18, label=w[0])
        front, best = [], float("inf")
        for p in sorted(members, key=lambda p: (cost(p), metric(p, "cycles"))):
            if metric(p, "cycles") < best:
                best = metric(p, "cycles")
                front.append(p)
        ax.step([cost(p) for p in front], [metric(p, "cycles") for p in front],
                where="post", color=dots.get_facecolor()[0], lw=1)
        for p in front:
            ax.annotate(label(p, doc["spec"]["keys"]), (cost(p), metric(p, "cycles")),
                        fontsize=5, xytext=(3, 3), textcoords="offset points")
    log2_if_spread(ax, [cost(p) for p in points])
    if chart["x"] == "on_chip_bytes":
        chart_style.size_axis(ax)
    ax.set_xlabel(x_label)
    ax.set_ylabel("cycles")
    ax.set_title(chart["title"])
    ax.legend(fontsize=7)
    return fig


def main(path, outdir):
    doc = json.load(open(path))
    chart_style.draw_all(
        [c for c in doc["charts"] if c["available"]],
        lambda chart: pareto(doc, chart) if chart["kind"] == "pareto" else curve(doc, chart),
        outdir)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
