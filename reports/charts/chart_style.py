"""The look of rtsim's charts, and deterministic PNG output.

Agg backend; PNGs carry no Software tag and no timestamp, so the same data gives the same
bytes. Files are written to a temporary name and renamed.
"""
import os
import signal
import sys
import traceback

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

RAY_TYPE_COLORS = {
    "camera": "#4c72b0", "shadow": "#55a868", "reflection": "#c44e52",
    "reflected_shadow": "#8172b2", "diffuse_gi": "#ccb974", "ao": "#64b5cd",
    "refraction": "#937860", "translucency": "#da8bc3",
}


def setup():
    plt.rcParams.update({
        "svg.hashsalt": "rtsim", "figure.dpi": 100, "font.size": 9,
        "axes.grid": True, "grid.alpha": 0.3, "axes.axisbelow": True,
        "axes.spines.top": False, "axes.spines.right": False,
    })


def color(ray_type):
    return RAY_TYPE_COLORS.get(ray_type, "#777777")


def save(fig, path):
    """Writes the chart whole or not at all: to PATH.tmp-PID, renamed over PATH."""
    tmp = path + ".tmp-%d" % os.getpid()
    try:
        # Tight bounding box: rotated tick labels and legends are never cut off at the edge.
        fig.savefig(tmp, format="png", dpi=100, metadata={"Software": None},
                    bbox_inches="tight", pad_inches=0.1)
        os.replace(tmp, path)
    except BaseException:  # also Ctrl-C and SIGTERM (see below): no temporary is left behind
        if os.path.exists(tmp):
            os.remove(tmp)
        raise
    finally:
        plt.close(fig)


# SIGTERM ends the script through the exception path, so save() cleans up as for Ctrl-C.
signal.signal(signal.SIGTERM, lambda number, frame: sys.exit(128 + number))


def size_text(n):
    """Bytes as rtsim writes sizes (traces/byte_size.h): 256K, 1M, 4M; 1.5M between units."""
    for shift, unit in ((40, "T"), (30, "G"), (20, "M"), (10, "K")):
        if n >= 1 << shift:
            return "%g%s" % (round(n / (1 << shift), 2), unit)
    return "%g" % n


def size_axis(ax, axis="x"):
    """Labels an axis that counts bytes as sizes: 256K, 1M, 4M."""
    from matplotlib.ticker import FuncFormatter, NullFormatter
    a = getattr(ax, axis + "axis")
    a.set_major_formatter(FuncFormatter(lambda v, _: size_text(v)))
    a.set_minor_formatter(NullFormatter())


def percent_scale(metric_name):
    """(factor, axis label suffix) of a metric: rates (hit, miss, utilisation fractions in the
    JSON) are drawn in percent."""
    if metric_name.endswith(("_rate", "utilisation", "_share")):
        return 100, " (%)"
    return 1, ""


def new(width=7.0, height=3.6, **kwargs):
    """A figure whose constrained layout keeps titles, labels and legends from overlapping."""
    setup()
    return plt.subplots(figsize=(width, height), layout="constrained", **kwargs)


def draw_all(items, draw, outdir):
    """Draws each item (a dict with "id" and "file") with draw(item) and saves it under outdir.

    A chart that fails is reported with its traceback and the others are still drawn; the
    script then exits non-zero naming the failed ones.
    """
    os.makedirs(os.path.join(outdir, "images"), exist_ok=True)
    failed = []
    for item in items:
        try:
            save(draw(item), os.path.join(outdir, item["file"]))
        except Exception:
            traceback.print_exc()
            failed.append(item["id"])
    if failed:
        sys.exit("failed: " + ", ".join(failed))
