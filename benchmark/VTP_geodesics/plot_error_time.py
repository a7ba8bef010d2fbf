#!/usr/bin/python3
"""Error versus time of every method of a vtp_benchmark CSV: one panel per mesh, one point per method and
parameter (x: processor seconds of the per-source computation, wall-clock seconds for the heat method, log scale; y: mean relative error against
exact VTP, in percent, log scale; exact VTP is drawn at the bottom edge). Methods whose distances go below
the exact ones by more than 1e-12 of the largest distance are drawn hollow; a method with an infinite mean error
is left out.

    /usr/bin/python3 plot_error_time.py results.csv error_time.png
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = defaultdict(lambda: defaultdict(list))
    with open(sys.argv[1], newline="") as f:
        for r in csv.DictReader(f):
            if not r["status"].startswith("ok"):
                continue
            key = "%s (%s V)" % (r["mesh"], r["vertices"])
            rows[key][r["method"]].append(r)
    meshes = sorted(rows)
    if not meshes:
        sys.exit("no successful run in " + sys.argv[1])
    columns = min(3, len(meshes))
    lines = (len(meshes) + columns - 1) // columns
    fig, axes = plt.subplots(lines, columns, figsize=(5.2 * columns, 4.2 * lines), squeeze=False)
    colours = {}
    palette = plt.get_cmap("tab10")
    floor = 1e-4  # percent: where the exact method is drawn
    for k, mesh in enumerate(meshes):
        ax = axes[k // columns][k % columns]
        for method, runs in sorted(rows[mesh].items()):
            # processor seconds where the benchmark measured them (the heat method: wall-clock seconds)
            cpu = sum(number(r["cpu_seconds"]) if not math.isnan(number(r["cpu_seconds"])) else number(r["seconds"])
                      for r in runs) / len(runs)
            err = [number(r["mean_pointwise_rel_err_vs_vtp"]) for r in runs]
            err = 100. * sum(e for e in err if not math.isnan(e)) / max(1, len(err))
            if not math.isfinite(err) or not math.isfinite(cpu):
                continue  # (no finite error to draw: e.g. the heat method giving 1.8e308 somewhere)
            below = max(number(r.get("max_below_vtp", "nan")) for r in runs)
            family = method.split(":")[0]
            colour = colours.setdefault(family, palette(len(colours) % 10))
            hollow = below > 1e-12
            ax.scatter([cpu], [max(err, floor)], s=46, facecolors="none" if hollow else [colour], edgecolors=[colour],
                       zorder=3)
            ax.annotate(method, (cpu, max(err, floor)), textcoords="offset points", xytext=(4, 4), fontsize=8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(mesh, fontsize=9)
        ax.set_xlabel("processor seconds per source")
        ax.set_ylabel("mean relative error vs VTP (%)")
        ax.grid(True, which="both", alpha=0.3)
    for k in range(len(meshes), lines * columns):
        axes[k // columns][k % columns].axis("off")
    fig.suptitle("Error versus time (hollow: below the exact distance somewhere; exact VTP at the bottom)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
