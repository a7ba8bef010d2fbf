#!/usr/bin/env python3
"""Turns the CSV written by vtp_benchmark into a Markdown table.

usage: make_table.py RESULTS.csv [-o TABLE.md] [--columns seconds,...]

One row per (mesh, method, threads): the median over the sources of each column
(maximum over the sources for the errors is available with --max-errors).
Only the Python standard library is used.
"""

import argparse
import csv
import math
import statistics
import sys

# (CSV column, Markdown header, format)
COLUMNS = [
    ("seconds", "Time (s)", "{:.4g}"),
    ("preprocessing_seconds", "Prep. (s)", "{:.3g}"),
    ("total_seconds", "Total (s)", "{:.4g}"),
    ("peak_rss_mb", "Peak RSS (MB)", "{:.1f}"),
    ("windows_created", "Windows created", "{:.0f}"),
    ("windows_propagated", "Windows propagated", "{:.0f}"),
    ("peak_window_bytes", "Peak window bytes", "{:.0f}"),
    ("max_abs_err_vs_vtp", "Max abs. err.", "{:.2e}"),
    ("max_rel_err_vs_vtp", "Max rel. err.", "{:.2e}"),
    ("mean_rel_err_vs_vtp", "Mean rel. err.", "{:.2e}"),
    ("speedup_vs_cgal", "Speedup vs CGAL", "{:.2f}"),
    ("mean_pointwise_rel_err_vs_vtp", "Mean rel. err. (%)", "{:.4f}"),
    ("max_pointwise_rel_err_vs_vtp", "Max rel. err. (%)", "{:.3f}"),
    ("speedup_vs_vtp", "Speedup vs VTP", "{:.2f}"),
    ("peak_live_windows", "Peak windows", "{:.0f}"),
    ("ns_per_window", "ns / window", "{:.0f}"),
    ("pseudo_source_share", "Pseudo-sources (%)", "{:.1f}"),
    ("cpu_seconds", "CPU time (s)", "{:.4g}"),
    ("cpu_ratio_vs_vtp", "CPU time of vtp / method", "{:.2f}"),
]
PERCENT_COLUMNS = {"mean_pointwise_rel_err_vs_vtp", "max_pointwise_rel_err_vs_vtp", "pseudo_source_share"}
DEFAULT_COLUMNS = ["seconds", "preprocessing_seconds", "peak_rss_mb", "windows_created",
                   "max_rel_err_vs_vtp", "speedup_vs_cgal"]
ERROR_COLUMNS = {"max_abs_err_vs_vtp", "max_rel_err_vs_vtp", "mean_rel_err_vs_vtp",
                 "mean_pointwise_rel_err_vs_vtp", "max_pointwise_rel_err_vs_vtp"}


def to_float(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return None if math.isnan(value) else value


def main(argv):
    parser = argparse.ArgumentParser(description="Markdown table from a vtp_benchmark CSV file.")
    parser.add_argument("csv", help="CSV file written by vtp_benchmark --csv")
    parser.add_argument("-o", "--output", help="write the table to this file (default: stdout)")
    parser.add_argument("--columns", default=",".join(DEFAULT_COLUMNS),
                        help="comma-separated CSV columns to show (default: %(default)s; 'all' for every column)")
    parser.add_argument("--max-errors", action="store_true",
                        help="report the maximum over the sources for the error columns instead of the median")
    args = parser.parse_args(argv)

    known = {name: (header, fmt) for name, header, fmt in COLUMNS}
    wanted = [c for c, _, _ in COLUMNS] if args.columns == "all" else [c for c in args.columns.split(",") if c]
    for c in wanted:
        if c not in known:
            parser.error("unknown column '%s' (known: %s)" % (c, ", ".join(known)))

    try:
        with open(args.csv, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        print("make_table.py: error: cannot read '%s': %s" % (args.csv, e.strerror), file=sys.stderr)
        return 2
    required = {"mesh", "vertices", "faces", "source", "method", "threads"} | set(wanted)
    if rows and not required.issubset(rows[0].keys()):
        missing = sorted(required - set(rows[0].keys()))
        print("make_table.py: error: '%s' lacks the columns %s" % (args.csv, ", ".join(missing)), file=sys.stderr)
        return 2

    # Group by (mesh, vertices, faces, method, threads), in the order of first appearance.
    groups = {}
    for row in rows:
        if row.get("status", "ok").split(" ")[0] != "ok":
            continue
        key = (row["mesh"], row["vertices"], row["faces"], row["method"], row["threads"])
        groups.setdefault(key, []).append(row)

    headers = ["Mesh", "#V", "#F", "Method", "Threads", "#Sources"] + [known[c][0] for c in wanted]
    lines = ["| " + " | ".join(headers) + " |",
             "|" + "|".join("---" if h in ("Mesh", "Method") else "--:" for h in headers) + "|"]
    for (mesh, nv, nf, method, threads), members in groups.items():
        cells = [mesh, nv, nf, method, threads, str(len({m["source"] for m in members}))]
        for c in wanted:
            values = [v for v in (to_float(m[c]) for m in members) if v is not None]
            if not values:
                cells.append("–")
                continue
            value = max(values) if (args.max_errors and c in ERROR_COLUMNS) else statistics.median(values)
            if c in PERCENT_COLUMNS:
                value *= 100.
            cells.append(known[c][1].format(value))
        lines.append("| " + " | ".join(cells) + " |")
    text = "\n".join(lines) + "\n"

    if args.output:
        try:
            with open(args.output, "w") as f:
                f.write(text)
        except OSError as e:
            print("make_table.py: error: cannot write '%s': %s" % (args.output, e.strerror), file=sys.stderr)
            return 2
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
