#!/usr/bin/env python3
"""The Python module vtp_geodesics against the C++ tools, on the same meshes and sources, in one run.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/VTP_geodesics/python_benchmark.py \
        --bin build/bin --threads 2 --repeat 2 --rows 6 MESH.off [MESH.off ...]

For each mesh, runs interleaved (tool, module, tool, module, ...) so that a shared machine's load falls on both
alike, and prints wall and processor seconds:

1. one source (vertex 0 and --sources more, evenly spaced): `vtp_geodesics MESH --source S --stats-json -`
   (its preprocessing_seconds + propagation_seconds, timed inside the tool) against `Solver(V, F)` +
   `solver.distances(S)` (timed around the Python calls; the mesh is read before, as the tool's reading is not
   counted either), and `solver.distances(S)` alone against the tool's propagation;
2. matrix rows per second with the same threads: `vtp_distance_matrix MESH --sources 0:R --float32` against
   `solver.matrix(range(R), dtype=numpy.float32)`. The tool's time includes reading, preprocessing and
   writing HDF5, so both are timed at R and at R0 = --rows0 rows and the rate is (R - R0) / (t(R) - t(R0));
3. peak memory of a float32 dense matrix of R rows, in a fresh process: peak RSS minus the RSS after importing
   numpy/scipy/vtp_geodesics, against the output + V + F + 64 MB.

Processor seconds (cpu_seconds) are user + system time of the process or child; on a machine shared with
other work, the ratios of one run matter more than the absolute times.
"""

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np


def cpu_self():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def cpu_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_child(cmd):
    c0, t0 = cpu_children(), time.perf_counter()
    p = subprocess.run(cmd, check=True, capture_output=True, text=True)
    return p.stdout, time.perf_counter() - t0, cpu_children() - c0


def timed(f):
    c0, t0 = cpu_self(), time.perf_counter()
    r = f()
    return r, time.perf_counter() - t0, cpu_self() - c0


MEMORY_PROBE = r"""
import sys, numpy, scipy.sparse, vtp_geodesics
def status(key):
    for line in open('/proc/self/status'):
        if line.startswith(key + ':'):
            return int(line.split()[1]) * 1024
V, F = vtp_geodesics.read_mesh(sys.argv[1])
rows, threads = int(sys.argv[2]), int(sys.argv[3])
base = status('VmRSS')            # interpreter, modules, V and F (and the reader's freed memory, if kept)
mesh_arrays = V.nbytes + F.nbytes
solver = vtp_geodesics.Solver(V, F, threads=threads)
after_solver = status('VmRSS')
M = solver.matrix(numpy.arange(rows), dtype=numpy.float32, threads=threads)
peak = status('VmHWM')
print(base, after_solver, peak, M.nbytes, mesh_arrays)
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--bin", default="build/bin", help="folder of vtp_geodesics and vtp_distance_matrix")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--sources", type=int, default=1, help="sources of the one-source test (vertex 0 and more)")
    ap.add_argument("--repeat", type=int, default=2, help="interleaved repetitions (the minimum is reported)")
    ap.add_argument("--rows", type=int, default=6, help="matrix rows R")
    ap.add_argument("--rows0", type=int, default=2, help="matrix rows R0 of the baseline run")
    ap.add_argument("--method", default="vtp", choices=["vtp", "pvtp", "avtp", "pavtp"])
    ap.add_argument("--json", help="also write the results as JSON to this file")
    ap.add_argument("--skip-matrix", action="store_true", help="only the one-source comparison")
    args = ap.parse_args()

    import vtp_geodesics

    tool = os.path.join(args.bin, "vtp_geodesics")
    matrix_tool = os.path.join(args.bin, "vtp_distance_matrix")
    results = []
    tmp = tempfile.mkdtemp(prefix="vtp_pybench_")
    print("machine: %d processors visible; threads %d; method %s; interleaved x%d (minimum reported)"
          % (os.cpu_count(), args.threads, args.method, args.repeat))
    for mesh in args.meshes:
        V, F = vtp_geodesics.read_mesh(mesh)
        n = len(V)
        sources = sorted(set([0] + [int(k * n / args.sources) for k in range(1, args.sources)]))
        r = {"mesh": mesh, "vertices": n, "faces": len(F), "sources": sources}
        # 1. one source, interleaved
        tool_runs, mod_runs = [], []
        for _ in range(args.repeat):
            out, wall, cpu = run_child([tool, mesh, "--source", ",".join(map(str, sources)), "--method", args.method,
                                        "--threads", str(args.threads), "--stats-json", "-"])
            st = json.loads(out)
            # the same run with --max-distance 0 (no propagation): its processor time is that of reading and
            # preprocessing, so the difference is the processor time of the propagation
            _, _, cpu0 = run_child([tool, mesh, "--source", ",".join(map(str, sources)), "--method", args.method,
                                    "--threads", str(args.threads), "--max-distance", "0", "--stats-json", "-"])
            tool_runs.append({"prep": st["preprocessing_seconds"], "prop": st["propagation_seconds"],
                              "wall": wall, "cpu": cpu, "cpu_without_propagation": cpu0})
            solver, t_solver, c_solver = timed(lambda: vtp_geodesics.Solver(V, F, threads=args.threads))
            d, t_dist, c_dist = timed(lambda: solver.distances(sources, method=args.method, threads=args.threads))
            mod_runs.append({"solver": t_solver, "distances": t_dist, "cpu": c_solver + c_dist,
                             "cpu_solver": c_solver, "cpu_distances": c_dist,
                             "prop": solver.statistics["seconds"],
                             "prep": solver.statistics["preprocessing_seconds"],
                             "build": solver.statistics["mesh_build_seconds"]})
            del solver
        tp = min(x["prep"] + x["prop"] for x in tool_runs)
        tprop = min(x["prop"] for x in tool_runs)
        mp = min(x["solver"] + x["distances"] for x in mod_runs)
        mprop = min(x["distances"] for x in mod_runs)
        mlib = min(x["prep"] + x["distances"] for x in mod_runs)
        r["one_source"] = {"tool_prep_plus_prop": tp, "module_solver_plus_distances": mp, "ratio": mp / tp,
                           "module_library_prep_plus_distances": mlib, "ratio_without_mesh_build": mlib / tp,
                           "tool_propagation": tprop, "module_distances": mprop, "ratio_propagation": mprop / tprop,
                           "tool_cpu_seconds_process": min(x["cpu"] for x in tool_runs),
                           "module_cpu_seconds": min(x["cpu"] for x in mod_runs),
                           "tool_runs": tool_runs, "module_runs": mod_runs}
        print("%s: %d vertices, sources %s" % (mesh, n, sources))
        print("  one source: tool prep+prop %.3f s, module Solver()+distances() %.3f s: ratio %.3f"
              % (tp, mp, mp / tp))
        print("              without building the mesh from V, F (Solver(): mesh %.3f s + library preprocessing "
              "%.3f s): %.3f s: ratio %.3f" % (min(x["build"] for x in mod_runs), min(x["prep"] for x in mod_runs),
                                               mlib, mlib / tp))
        print("              tool propagation %.3f s, module distances() %.3f s: ratio %.3f"
              % (tprop, mprop, mprop / tprop))
        print("              cpu_seconds: tool process %.2f (with reading), module %.2f"
              % (r["one_source"]["tool_cpu_seconds_process"], r["one_source"]["module_cpu_seconds"]))
        tool_prop_cpu = min(x["cpu"] - x["cpu_without_propagation"] for x in tool_runs)
        mod_prop_cpu = min(x["cpu_distances"] for x in mod_runs)
        r["one_source"]["tool_propagation_cpu_seconds"] = tool_prop_cpu
        r["one_source"]["module_distances_cpu_seconds"] = mod_prop_cpu
        print("              cpu_seconds of the propagation: tool %.3f (run - run with --max-distance 0), module "
              "distances() %.3f: ratio %.3f" % (tool_prop_cpu, mod_prop_cpu, mod_prop_cpu / tool_prop_cpu))
        if args.skip_matrix:
            results.append(r)
            continue
        # 2. matrix rows per second
        solver = vtp_geodesics.Solver(V, F, threads=args.threads)
        m_method = "avtp" if "avtp" in args.method else "vtp"
        tt = {args.rows: [], args.rows0: []}
        mt = {args.rows: [], args.rows0: []}
        tc, mc = {args.rows: [], args.rows0: []}, {args.rows: [], args.rows0: []}
        for _ in range(args.repeat):
            for rows in (args.rows0, args.rows):
                h5 = os.path.join(tmp, "m.h5")
                _, wall, cpu = run_child([matrix_tool, mesh, "--sources", "0:%d" % rows, "--output", h5, "--float32",
                                          "--method", m_method, "--threads", str(args.threads), "--force", "--quiet"])
                tt[rows].append(wall)
                tc[rows].append(cpu)
                _, wall, cpu = timed(lambda: solver.matrix(np.arange(rows), dtype=np.float32, threads=args.threads,
                                                           method=m_method))
                mt[rows].append(wall)
                mc[rows].append(cpu)
        dr = args.rows - args.rows0
        tool_rate = dr / (min(tt[args.rows]) - min(tt[args.rows0]))
        mod_rate = dr / (min(mt[args.rows]) - min(mt[args.rows0]))
        mod_rate_direct = args.rows / min(mt[args.rows])
        r["matrix"] = {"rows": args.rows, "rows0": args.rows0, "tool_rows_per_second": tool_rate,
                       "module_rows_per_second": mod_rate, "module_rows_per_second_direct": mod_rate_direct,
                       "ratio": mod_rate / tool_rate, "tool_seconds": tt, "module_seconds": mt,
                       "tool_cpu_seconds": tc, "module_cpu_seconds": mc}
        print("  matrix: vtp_distance_matrix %.3f rows/s, module %.3f rows/s (marginal, %d - %d rows): ratio %.3f; "
              "module %d rows in %.2f s = %.3f rows/s"
              % (tool_rate, mod_rate, args.rows, args.rows0, mod_rate / tool_rate, args.rows, min(mt[args.rows]),
                 mod_rate_direct))
        print("          cpu_seconds at %d rows: tool %.2f, module %.2f"
              % (args.rows, min(tc[args.rows]), min(mc[args.rows])))
        del solver
        # 3. memory of a float32 dense matrix, in a fresh process
        env = dict(os.environ)
        p = subprocess.run([sys.executable, "-c", MEMORY_PROBE, mesh, str(args.rows), str(args.threads)],
                           check=True, capture_output=True, text=True, env=env)
        base, after_solver, peak, out_bytes, mesh_bytes = map(int, p.stdout.split())
        extra = peak - base - out_bytes
        r["memory"] = {"rss_after_read": base, "rss_after_solver": after_solver, "peak_rss": peak,
                       "output_bytes": out_bytes, "mesh_array_bytes": mesh_bytes,
                       "peak_minus_base_minus_output": extra, "solver_bytes": after_solver - base,
                       "bar_ok": extra <= 64 * 2 ** 20}
        print("  memory (float32, %d rows): peak RSS %.1f MB = after read_mesh %.1f MB (interpreter, modules, "
              "V+F %.1f MB) + output %.1f MB + %.1f MB (of which the solver %.1f MB): %s 64 MB"
              % (args.rows, peak / 2 ** 20, base / 2 ** 20, mesh_bytes / 2 ** 20, out_bytes / 2 ** 20,
                 extra / 2 ** 20, (after_solver - base) / 2 ** 20, "<=" if extra <= 64 * 2 ** 20 else ">"))
        results.append(r)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
