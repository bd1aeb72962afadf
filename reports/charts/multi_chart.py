#!/usr/bin/python3
"""Chart of `rtsim multi-device` (Harada & Fujita 2014 split strategies side by side).

Usage: multi_chart.py DIR  -- reads DIR/frames.csv and DIR/devices.csv, writes DIR/chart.png.
Top row: each strategy's per-device tracing time per frame. Bottom row: the maximum deviation
from the mean (%), the speed-up against one device and the copy overhead, every strategy.
"""
import csv
import os
import sys

import chart_style


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def by_strategy(rows):
    out = {}
    for row in rows:
        out.setdefault(row["strategy"], []).append(row)
    return out


def main(folder):
    frames = by_strategy(read_csv(os.path.join(folder, "frames.csv")))
    devices = by_strategy(read_csv(os.path.join(folder, "devices.csv")))
    names = list(frames)
    columns = max(len(names), 3)
    fig, axes = chart_style.new(4.6 * columns, 7.5, nrows=2, ncols=columns, squeeze=False)
    top = None
    for i, name in enumerate(names):
        ax = axes[0][i]
        per_device = {}
        for row in devices[name]:
            per_device.setdefault(int(row["device"]), []).append(
                (int(row["frame"]), float(row["trace_ns"]) / 1000))
        for device, points in sorted(per_device.items()):
            ax.plot([p[0] for p in points], [p[1] for p in points], marker=".",
                    label=f"device {device}")
        ax.set_title(f"{name} split: tracing time per device")
        ax.set_xlabel("frame")
        ax.set_ylabel("us")
        ax.legend(fontsize="small")
        top = max(top or 0, ax.get_ylim()[1])
    for i in range(len(names)):
        axes[0][i].set_ylim(0, top)
    for i in range(len(names), columns):
        axes[0][i].axis("off")
    panels = [("max_deviation_pct", "max deviation from the mean (%, log above 10)", 1.0),
              ("speedup", "speed-up vs one device", 1.0),
              ("copy_overhead_ns", "copy overhead (us)", 1e-3)]
    for ax, (key, title, scale) in zip(axes[1], panels):
        for name in names:
            rows = frames[name]
            ax.plot([int(r["frame"]) for r in rows], [float(r[key]) * scale for r in rows],
                    marker=".", label=name)
        if key == "max_deviation_pct":
            ax.axhline(3.0, color="grey", linestyle=":", linewidth=1, label="3%")
            # Linear up to 10%, logarithmic above: a few % stays readable next to static's 80%.
            ax.set_yscale("symlog", linthresh=10.0, linscale=2.0)
            ax.set_yticks([0, 2, 4, 6, 8, 10, 20, 50, 100])
            ax.set_yticklabels(["0", "2", "4", "6", "8", "10", "20", "50", "100"])
            ax.minorticks_off()
        ax.set_title(title)
        ax.set_xlabel("frame")
        ax.set_ylim(bottom=0)
        ax.legend(fontsize="small")
    for i in range(len(panels), columns):
        axes[1][i].axis("off")
    chart_style.save(fig, os.path.join(folder, "chart.png"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: multi_chart.py DIR")
    main(sys.argv[1])
