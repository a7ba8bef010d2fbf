#!/usr/bin/python3
"""Plots the speed/accuracy trade of the approximate variants against lambda.

usage: plot_lambda.py RESULTS.csv -o lambda.png

Reads the CSV written by `vtp_benchmark --methods vtp,avtp:2,avtp:4,... --csv RESULTS.csv` and
draws, for each mesh, the mean pointwise relative error against exact VTP (left, log scale) and
the speedup over exact VTP (right) as functions of lambda (median over the sources).
Needs python3-matplotlib (Debian package).
"""

import argparse
import csv
import math
import statistics
import sys


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("csv")
    parser.add_argument("-o", "--output", required=True, help="PNG file to write")
    parser.add_argument("--method", default="avtp", help="avtp (default) or pavtp")
    args = parser.parse_args(argv)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    series = {}  # mesh -> lambda -> (errors, speedups)
    with open(args.csv, newline="") as f:
        for row in csv.DictReader(f):
            label = row["method"]
            if not label.startswith(args.method + ":") or not row["status"].startswith("ok"):
                continue
            lam = float(label.split(":")[-1])
            mesh = "%s (%s V)" % (row["mesh"], row["vertices"])
            try:
                err = float(row["mean_pointwise_rel_err_vs_vtp"])
                speed = float(row["speedup_vs_vtp"])
            except ValueError:
                continue
            if math.isnan(err) or math.isnan(speed):
                continue
            e, s = series.setdefault(mesh, {}).setdefault(lam, ([], []))
            e.append(err)
            s.append(speed)
    if not series:
        print("plot_lambda.py: error: no %s rows in %s" % (args.method, args.csv), file=sys.stderr)
        return 2

    fig, (ax_err, ax_speed) = plt.subplots(1, 2, figsize=(11, 4.2))
    for mesh, by_lambda in sorted(series.items()):
        lams = sorted(by_lambda)
        errs = [100. * statistics.median(by_lambda[l][0]) for l in lams]
        speeds = [statistics.median(by_lambda[l][1]) for l in lams]
        ax_err.plot(lams, [max(e, 1e-9) for e in errs], marker="o", label=mesh)
        ax_speed.plot(lams, speeds, marker="o", label=mesh)
    for ax in (ax_err, ax_speed):
        ax.set_xscale("log", base=2)
        ax.set_xlabel("lambda (reset period, in mean edge lengths)")
        ax.grid(True, which="both", alpha=0.3)
    ax_err.set_yscale("log")
    ax_err.set_ylabel("mean relative error vs exact VTP (%)")
    ax_speed.set_ylabel("speedup over exact VTP (propagation time)")
    ax_speed.axhline(1.0, color="gray", linewidth=0.8)
    ax_err.legend(fontsize=8)
    fig.suptitle("%s: accuracy and speed against lambda" % args.method.upper())
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
