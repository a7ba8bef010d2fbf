#!/usr/bin/env python3
"""The log map in the tool and in Python against the distance run it rides on, on one mesh, in one run.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/VTP_geodesics/log_map_time.py \
        --tool build/bin/vtp_geodesics --repeat 7 MESH.off

Interleaved rounds (so that a shared machine's load falls on all alike), one thread, source 0:
1. the tool: `vtp_geodesics MESH --source 0 --threads 1` with `--output FILE` (distances), `--log-map-output FILE`,
   and `--log-map-output FILE --log-map-strict`, each with `--stats-json`: its propagation_seconds and
   total_seconds (wall clock, timed inside the tool), the processor seconds of the process (user + system) and,
   with --no-python, its peak_rss_mb (a child forked from a Python process holding the mesh inherits its peak);
2. Python, on a `Solver(V, F, threads=1)` built once: `solver.distances(0)`, `solver.log_map(0)` and
   `solver.log_map(0, strict=True)`, wall and processor seconds around the calls.
Prints the medians and their ratios to the distance run.
"""

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("mesh")
    p.add_argument("--tool", required=True, help="the vtp_geodesics executable")
    p.add_argument("--repeat", type=int, default=7)
    p.add_argument("--source", type=int, default=0)
    p.add_argument("--no-python", action="store_true", help="the tool only")
    a = p.parse_args()

    solver = None
    if not a.no_python:
        import vtp_geodesics
        V, F = vtp_geodesics.read_mesh(a.mesh)
        solver = vtp_geodesics.Solver(V, F, threads=1)
    work = tempfile.mkdtemp(prefix="log_map_time_")
    tool_runs = [("distances (--output)", ["--output"]), ("--log-map-output", ["--log-map-output"]),
                 ("--log-map-output --log-map-strict", ["--log-map-strict", "--log-map-output"])]
    python_calls = [("distances(S)", lambda: solver.distances(a.source)), ("log_map(S)", lambda: solver.log_map(a.source)),
                    ("log_map(S, strict=True)", lambda: solver.log_map(a.source, strict=True))]
    tool = {name: [] for name, _ in tool_runs}
    py = {name: [] for name, _ in python_calls}
    for _ in range(a.repeat):
        for name, options in tool_runs:
            out = os.path.join(work, "out.txt")
            c0 = children_cpu()
            r = subprocess.run([a.tool, a.mesh, "--source", str(a.source), "--threads", "1"] + options
                               + [out, "--stats-json", "-"], check=True, capture_output=True, text=True)
            s = json.loads(r.stdout)
            tool[name].append((s["propagation_seconds"], s["total_seconds"], children_cpu() - c0, s["peak_rss_mb"]))
        if solver is not None:
            for name, call in python_calls:
                t0, c0 = time.perf_counter(), time.process_time()
                call()
                py[name].append((time.perf_counter() - t0, time.process_time() - c0))
    print("%s, source %d, one thread, medians of %d interleaved rounds" % (a.mesh, a.source, a.repeat))
    base = None
    for name, _ in tool_runs:
        m = [statistics.median(x[k] for x in tool[name]) for k in range(4)]
        base = base or m
        # (a child forked from this process inherits its peak RSS: shown only without Python)
        rss = ", peak rss %.1f MB" % m[3] if solver is None else ""
        print("tool   %-36s propagation %.3f s (x%.3f), total %.3f s (x%.3f), cpu %.3f s (x%.3f)%s"
              % (name, m[0], m[0] / base[0], m[1], m[1] / base[1], m[2], m[2] / base[2], rss))
    if solver is not None:
        base = None
        for name, _ in python_calls:
            m = [statistics.median(x[k] for x in py[name]) for k in range(2)]
            base = base or m
            print("python %-36s wall %.3f s (x%.3f), cpu %.3f s (x%.3f)" % (name, m[0], m[0] / base[0], m[1],
                                                                            m[1] / base[1]))


if __name__ == "__main__":
    sys.exit(main())
