#!/usr/bin/env python3
"""Figures of vtp_distance_matrix for README.md ("Many sources"), measured with the tool itself.

  matrix_figures.py threads  --tool BIN MESH [--rows K] [--repeat R]   rows/s with 1 and 2 threads
  matrix_figures.py mpi      --tool BIN MESH [--rows K] [--repeat R]   rows/s of 1 process, mpirun -np 1 and -np 2 (1 thread each)
  matrix_figures.py allpairs --tool BIN MESH [--threads T] [--float32]  the whole matrix, time and peak RSS
  matrix_figures.py rss      --tool BIN MESH [--rows K]                dense float32 all-pairs run, RSS every few
                                                                        seconds over the first K rows, then stopped
  matrix_figures.py subdivide IN.off OUT.off                            1-to-4 midpoint subdivision (OFF)

Variants are run in turn, R times (interleaved), and the median is kept; the machine's load (from
/proc/loadavg) is printed with every measurement. Output files go to --work (default /tmp) and are
removed afterwards.
"""

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import time


def load():
    with open("/proc/loadavg") as f:
        return f.read().split()[0]


def mpirun():
    command = ["mpirun", "--oversubscribe"]
    if os.geteuid() == 0:
        command.append("--allow-run-as-root")
    return command


def cpu_seconds():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(command, out):
    """Wall-clock and CPU seconds (of the process and its children) of one run."""
    for f in [out, out + ".part", out + ".part.journal"]:
        if os.path.exists(f):
            os.remove(f)
    cpu = cpu_seconds()
    start = time.time()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    seconds = time.time() - start
    os.remove(out)
    return seconds, cpu_seconds() - cpu


def rates(a, variants):
    """variants: list of (label, command builder(out) -> list). Returns {label: median rows/s}."""
    out = os.path.join(a.work, "figures.h5")
    results = {label: [] for label, _ in variants}
    for r in range(a.repeat):
        for label, command in variants:
            s, cpu = timed(command(out), out)
            results[label].append(a.rows / s)
            # rows per CPU second: what the rows cost, whatever else runs on the machine
            print("# repeat %d  %-22s %7.1f rows/s  (%.2f s, %.2f CPU s, %.1f rows per CPU s, load %s)"
                  % (r + 1, label, a.rows / s, s, cpu, a.rows / cpu, load()), flush=True)
    return {label: statistics.median(v) for label, v in results.items()}


def threads(a):
    base = [a.tool, a.mesh, "--sources", "0:%d" % a.rows, "--float32", "--quiet"]
    r = rates(a, [("1 thread", lambda o: base + ["--output", o, "--threads", "1"]),
                  ("2 threads", lambda o: base + ["--output", o, "--threads", "2"])])
    print("| %s | %d rows | 1 thread: %.1f rows/s | 2 threads: %.1f rows/s | %.2fx |"
          % (os.path.basename(a.mesh), a.rows, r["1 thread"], r["2 threads"], r["2 threads"] / r["1 thread"]))


def mpi(a):
    base = [a.tool, a.mesh, "--sources", "0:%d" % a.rows, "--float32", "--quiet", "--threads", "1"]
    r = rates(a, [("1 process", lambda o: base + ["--output", o]),
                  ("mpirun -np 1", lambda o: mpirun() + ["-np", "1"] + base + ["--output", o]),
                  ("mpirun -np 2", lambda o: mpirun() + ["-np", "2"] + base + ["--output", o])])
    print("| %s | %d rows | 1 process: %.1f | mpirun -np 1: %.1f | mpirun -np 2: %.1f rows/s | %.2fx |"
          % (os.path.basename(a.mesh), a.rows, r["1 process"], r["mpirun -np 1"], r["mpirun -np 2"],
             r["mpirun -np 2"] / r["mpirun -np 1"]))


def allpairs(a):
    out = os.path.join(a.work, "allpairs.h5")
    for f in [out, out + ".part", out + ".part.journal"]:
        if os.path.exists(f):
            os.remove(f)
    command = ["/usr/bin/time", "-f", "%e %M %U %S", a.tool, a.mesh, "--sources", "all", "--output", out,
               "--threads", str(a.threads), "--quiet"] + (["--float32"] if a.float32 else [])
    print("# load before: %s" % load(), flush=True)
    p = subprocess.run(command, check=True, stderr=subprocess.PIPE, universal_newlines=True)
    seconds, kb, user, system = p.stderr.split()[-4:]
    size = os.path.getsize(out)
    print("| %s | all pairs | %s | %d threads | %.1f s | %.0f CPU s | %.0f MB file | peak RSS %.0f MB | load after %s |"
          % (os.path.basename(a.mesh), "float32" if a.float32 else "float64", a.threads, float(seconds),
             float(user) + float(system), size / 1e6, int(kb) / 1024., load()))
    os.remove(out)


def rss(a):
    out = os.path.join(a.work, "rss.h5")
    for f in [out, out + ".part", out + ".part.journal"]:
        if os.path.exists(f):
            os.remove(f)
    p = subprocess.Popen([a.tool, a.mesh, "--sources", "all", "--output", out, "--float32", "--progress",
                          "--threads", str(a.threads)], stderr=subprocess.PIPE, universal_newlines=True)
    print("| seconds | rows done | RSS (MB) | load |")
    print("|--:|--:|--:|--:|")
    start = time.time()
    last = -100.
    peak = 0
    while p.poll() is None:
        line = p.stderr.readline()
        m = re.match(r"^vtp_distance_matrix: (\d+)/(\d+) rows", line)
        if not m:
            continue
        with open("/proc/%d/status" % p.pid) as f:
            kb = int(re.search(r"VmRSS:\s+(\d+)", f.read()).group(1))
        peak = max(peak, kb)
        done = int(m.group(1))
        now = time.time() - start
        if now - last >= a.every or done >= a.rows:
            print("| %.0f | %d | %.1f | %s |" % (now, done, kb / 1024., load()), flush=True)
            last = now
        if done >= a.rows:
            break
    p.kill()
    p.wait()
    print("# peak RSS seen %.1f MB; file size %.2f GB (reserved: a sparse file until written)"
          % (peak / 1024., os.path.getsize(out + ".part") / 1e9))
    for f in [out + ".part", out + ".part.journal", out + ".part.lock"]:
        os.remove(f)


def subdivide(a):
    points, faces = [], []
    with open(a.input) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    for i in range(nv):
        points.append(tuple(float(x) for x in tokens[at:at + 3]))
        at += 3
    for i in range(nf):
        k = int(tokens[at])
        faces.append(tuple(int(x) for x in tokens[at + 1:at + 1 + k]))
        at += 1 + k
    middle = {}

    def mid(u, v):
        key = (min(u, v), max(u, v))
        if key not in middle:
            middle[key] = len(points)
            points.append(tuple((p + q) / 2 for p, q in zip(points[u], points[v])))
        return middle[key]
    new_faces = []
    for (x, y, z) in faces:
        xy, yz, zx = mid(x, y), mid(y, z), mid(z, x)
        new_faces += [(x, xy, zx), (xy, y, yz), (zx, yz, z), (xy, yz, zx)]
    with open(a.output, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(new_faces)))
        for p in points:
            f.write("%.17g %.17g %.17g\n" % p)
        for t in new_faces:
            f.write("3 %d %d %d\n" % t)
    print("%s: %d vertices, %d faces" % (a.output, len(points), len(new_faces)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("what", choices=["threads", "mpi", "allpairs", "rss", "subdivide"])
    parser.add_argument("mesh", nargs="+")
    parser.add_argument("--tool", default="build/bin/vtp_distance_matrix")
    parser.add_argument("--rows", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--every", type=float, default=10.)
    parser.add_argument("--float32", action="store_true")
    parser.add_argument("--work", default="/tmp")
    a = parser.parse_args()
    if a.what == "subdivide":
        a.input, a.output = a.mesh
    else:
        a.mesh = a.mesh[0]
    globals()[a.what](a)


if __name__ == "__main__":
    main()
