#!/usr/bin/env python3
"""Tests of the vtp_distance_matrix tool, reading its files back with h5py and scipy.sparse as users do.

Run by ctest, one test per name (see CMakeLists.txt):
  distance_matrix_test.py NAME --tool vtp_distance_matrix --geodesics vtp_geodesics --data DIR
                          --cli-data DIR --work DIR [--mpirun mpirun]
Names: rows_single_source symmetric dense_sparse float32 threads mpi2 mpi3 resume resume_mpi
       bad_input protect_output full_disk progress help polar
Expected values come from invariants and from another program (vtp_geodesics, one source at a time),
never from stored outputs.
"""

import argparse
import filecmp
import hashlib
import os
import pty
import re
import resource
import select
import shutil
import signal
import subprocess
import sys
import time

import h5py
import numpy as np
import scipy.sparse

A = None  # command-line arguments
FAILURES = []
PROGRAM = "vtp_distance_matrix"


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("FAIL: " + message, flush=True)
    return condition


def work(name):
    return os.path.join(A.work, name)


def mesh(name):
    return os.path.join(A.data, name)


def tool_command(args, ranks=0):
    command = [A.tool] + [str(a) for a in args]
    if ranks > 0:
        launcher = [A.mpirun, "--oversubscribe", "-np", str(ranks)]
        if os.geteuid() == 0:
            launcher.insert(1, "--allow-run-as-root")
        command = launcher + command
    return command


MPI_LEAK_CHECK = False


def tool_environment(ranks):
    """The environment of a run. Under mpirun in the ASan build (VTP_TEST_MPI_LSAN_OPTIONS set by
    CMakeLists.txt): the leak check needs suppressions for Open MPI's allocations at exit, and slow
    stack unwinding to match them (see lsan_openmpi.supp); it is done in the runs of test mpi2 only,
    and off in the other MPI runs (the same code runs without MPI, leak-checked, in the other tests)."""
    env = dict(os.environ)
    if ranks > 0:
        # in containers (CI), Open MPI's shared-memory single copy (CMA) may be forbidden: plain copies
        env.setdefault("OMPI_MCA_btl_vader_single_copy_mechanism", "none")
    lsan = env.pop("VTP_TEST_MPI_LSAN_OPTIONS", "")
    if ranks > 0 and lsan:
        if MPI_LEAK_CHECK:
            env["LSAN_OPTIONS"] = lsan
            env["OMPI_MCA_mca_base_component_disable_dlclose"] = "1"
        else:
            env["ASAN_OPTIONS"] = (env.get("ASAN_OPTIONS", "") + ":detect_leaks=0").lstrip(":")
    return env


def run(args, expect=0, ranks=0, limit_file_size=None):
    """Runs the tool; checks its exit code; returns (stdout, stderr)."""
    def limit():
        if limit_file_size is not None:
            # a write beyond the limit fails with EFBIG, as on a full disk (instead of a signal)
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit_file_size, limit_file_size))
    p = subprocess.run(tool_command(args, ranks), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True, preexec_fn=limit, timeout=600, env=tool_environment(ranks))
    if not check(p.returncode == expect, "exit code %d, expected %d: %s\nstderr: %s"
                 % (p.returncode, expect, " ".join(tool_command(args, ranks)), p.stderr)):
        raise SystemExit(1)
    return p.stdout, p.stderr


def read_dense(path):
    with h5py.File(path, "r") as f:
        return f["sources"][:], f["distances"][:]


def read_csr(path):
    with h5py.File(path, "r") as f:
        g = f["distances"]
        check(g["indices"].dtype == np.int64 and g["indptr"].dtype == np.int64, "CSR index types are int64")
        shape = tuple(int(x) for x in g.attrs["shape"])
        m = scipy.sparse.csr_matrix((g["data"][:], g["indices"][:], g["indptr"][:]), shape=shape)
        return f["sources"][:], m


def bitwise_equal(a, b):
    a = np.asarray(a)
    b = np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and np.array_equal(a.view(np.uint8), b.view(np.uint8))


def h5_contents(path):
    """Every dataset (bytes) and attribute of an HDF5 file, by name."""
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                out["dataset " + name] = (obj.dtype.str, obj.shape, obj[()].tobytes())
            for k, v in obj.attrs.items():
                out["attribute %s@%s" % (name, k)] = repr(v)
        visit("/", f)
        f.visititems(visit)
    return out


def same_file(a, b, what):
    """The two outputs are the same bytes (and, to say what differs, the same contents)."""
    ca, cb = h5_contents(a), h5_contents(b)
    for k in sorted(set(ca) | set(cb)):
        check(ca.get(k) == cb.get(k), "%s: %s differs between %s and %s" % (what, k, a, b))
    check(filecmp.cmp(a, b, shallow=False), "%s: %s and %s are not the same bytes" % (what, a, b))


def single_source(mesh_file, source, extra=()):
    """Distances from one source computed by vtp_geodesics (text, %.17g: exact round trip)."""
    out = work("single.txt")
    p = subprocess.run([A.geodesics, mesh_file, "--source", str(source), "--output", out] + list(extra),
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    if not check(p.returncode == 0, "vtp_geodesics failed: " + p.stderr):
        raise SystemExit(1)
    with open(out) as f:
        return np.array([float(line) for line in f])


def fresh(*names):
    for n in names:
        for f in os.listdir(A.work):
            if f == n or f.startswith(n + ".part"):
                os.remove(work(f))


def file_hash(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


# ------------------------------------------------------------------------------------------------

def test_rows_single_source():
    """Each row equals a single-source run of vtp_geodesics, bitwise, for VTP, AVTP, VSP and VSP2, on a mesh with
    boundaries and on a mesh that is repaired (a vertex cut in two copies, an isolated point)."""
    cases = [("elephant-with-holes.off", A.data, "0,17,1000,2797,1500", []),
             ("elephant-with-holes.off", A.data, "2000,5", ["--method", "avtp", "--lambda", "4"]),
             ("elephant-with-holes.off", A.data, "3,900", ["--method", "vsp"]),
             ("elephant-with-holes.off", A.data, "3,900", ["--method", "vsp2"]),
             ("nonmanifold_vertex.off", A.cli_data, "all", [])]
    for name, folder, sources, method in cases:
        out = work("rows.h5")
        fresh("rows.h5")
        run([os.path.join(folder, name), "--sources", sources, "--output", out, "--threads", 2] + method)
        s, d = read_dense(out)
        check(d.dtype == np.float64 and s.dtype == np.int64, "types of /distances and /sources")
        for i, v in enumerate(s):
            ref = single_source(os.path.join(folder, name), v, method)
            check(bitwise_equal(d[i], ref), "%s %s: row %d (source %d) differs from vtp_geodesics (max %g)"
                  % (name, " ".join(method), i, v, np.max(np.abs(d[i] - ref))))


def test_symmetric():
    """Exact all-pairs matrices are symmetric to 1e-12 * max, with a zero diagonal."""
    for name in ["sphere.off", "elephant_395.off", "elephant-with-holes_565.off"]:
        out = work("all.h5")
        fresh("all.h5")
        run([mesh(name), "--sources", "all", "--output", out, "--threads", 2])
        s, d = read_dense(out)
        check(d.shape == (len(s), len(s)) and np.array_equal(s, np.arange(len(s))), name + ": shape")
        check(np.isfinite(d).all(), name + ": every vertex is reached")
        check((np.diag(d) == 0).all() and (d >= 0).all(), name + ": zero diagonal, no negative distance")
        asym = np.max(np.abs(d - d.T))
        check(asym <= 1e-12 * d.max(), "%s: not symmetric: %g > 1e-12 * %g" % (name, asym, d.max()))


def test_dense_sparse():
    """With --max-distance R, the CSR rows hold exactly the dense entries <= R, with the same values."""
    m = mesh("elephant.off")
    dense, dense32 = work("dense.h5"), work("dense32.h5")
    fresh("dense.h5", "dense32.h5")
    run([m, "--sources", "0:40", "--output", dense, "--threads", 2])
    run([m, "--sources", "0:40", "--output", dense32, "--threads", 2, "--float32"])
    s, d = read_dense(dense)
    _, d32 = read_dense(dense32)
    for r_factor in [0.3, 0.0]:
        for float32, ref in [(False, d), (True, d32)]:
            R = r_factor * float(d.max())
            out = work("sparse.h5")
            fresh("sparse.h5")
            run([m, "--sources", "0:40", "--output", out, "--threads", 2, "--max-distance", repr(R)]
                + (["--float32"] if float32 else []))
            s2, c = read_csr(out)
            what = "R = %g%s" % (R, " float32" if float32 else "")
            check(np.array_equal(s, s2), what + ": same sources")
            check(c.shape == d.shape and c.has_sorted_indices, what + ": shape, sorted indices")
            check(c.dtype == ref.dtype, what + ": value type")
            for i in range(d.shape[0]):
                lo, hi = c.indptr[i], c.indptr[i + 1]
                inside = np.nonzero(d[i] <= R)[0]
                check(np.array_equal(c.indices[lo:hi], inside), "%s: row %d has other entries" % (what, i))
                check(bitwise_equal(c.data[lo:hi], ref[i][inside]), "%s: row %d has other values" % (what, i))
            if R == 0:
                check(c.nnz == d.shape[0], "R = 0: only the sources themselves")
    # unreachable vertices are absent, also with an infinite limit
    nmv = os.path.join(A.cli_data, "nonmanifold_vertex.off")
    a, b = work("nmv_dense.h5"), work("nmv_inf.h5")
    fresh("nmv_dense.h5", "nmv_inf.h5")
    run([nmv, "--sources", "all", "--output", a])
    run([nmv, "--sources", "all", "--output", b, "--max-distance", "inf"])
    _, d = read_dense(a)
    _, c = read_csr(b)
    check(np.isinf(d).any(), "nonmanifold_vertex.off has unreachable vertices")
    for i in range(d.shape[0]):
        lo, hi = c.indptr[i], c.indptr[i + 1]
        check(np.array_equal(c.indices[lo:hi], np.nonzero(np.isfinite(d[i]))[0]), "R = inf: row %d" % i)
        check(bitwise_equal(c.data[lo:hi], d[i][np.isfinite(d[i])]), "R = inf: values of row %d" % i)


def test_float32():
    """float32 output is the float64 output rounded to nearest (inf kept)."""
    m = os.path.join(A.cli_data, "nonmanifold_vertex.off")  # has unreachable vertices
    for name, mesh_file, sources in [("nmv", m, "all"), ("elephant", mesh("elephant.off"), "3,1,4,1,5,9,2,6")]:
        a, b = work(name + "64.h5"), work(name + "32.h5")
        fresh(name + "64.h5", name + "32.h5")
        run([mesh_file, "--sources", sources, "--output", a])
        run([mesh_file, "--sources", sources, "--output", b, "--float32"])
        _, d64 = read_dense(a)
        _, d32 = read_dense(b)
        check(d32.dtype == np.float32, name + ": float32 dataset")
        check(bitwise_equal(d32, d64.astype(np.float32)), name + ": float32 = float64 rounded")
        if name == "nmv":
            check(np.isinf(d32).sum() == np.isinf(d64).sum() > 0, name + ": inf kept")


def test_threads():
    """The number of threads does not change the file (dense and sparse)."""
    m = mesh("elephant-with-holes.off")
    for extra in [[], ["--max-distance", "0.4", "--float32"], ["--max-distance", "0.3", "--polar"]]:
        outs = []
        for t in [1, 2, 3]:
            out = work("threads%d.h5" % t)
            fresh("threads%d.h5" % t)
            run([m, "--sources", "100:160", "--output", out, "--threads", t] + extra)
            outs.append(out)
        for o in outs[1:]:
            same_file(outs[0], o, "threads " + " ".join(extra))


def mpi_test(ranks):
    """mpirun -np N gives the same file as one process (dense and sparse); progress from one rank."""
    if not A.mpirun:
        print("SKIP: built without MPI")
        return
    m = mesh("elephant.off")
    for extra in [[], ["--max-distance", "0.35"], ["--max-distance", "0.3", "--polar"]]:
        single, multi = work("single%d.h5" % ranks), work("mpi%d.h5" % ranks)
        fresh("single%d.h5" % ranks, "mpi%d.h5" % ranks)
        run([m, "--sources", "0:40", "--output", single, "--threads", 2] + extra)
        _, err = run([m, "--sources", "0:40", "--output", multi, "--threads", 1, "--progress"] + extra, ranks=ranks)
        same_file(single, multi, "mpirun -np %d %s" % (ranks, " ".join(extra)))
        finals = [l for l in err.splitlines() if re.match(r"^%s: 40/40 rows \(100\.0%%\), [0-9.]+ rows/s, [0-9]+ s$"
                                                          % PROGRAM, l)]
        check(len(finals) == 1, "one final progress line under MPI, got:\n" + err)


def test_mpi2():
    global MPI_LEAK_CHECK
    MPI_LEAK_CHECK = True
    mpi_test(2)


def test_mpi3():
    mpi_test(3)


class Timing(Exception):
    """A stop did not fall where it was meant to (the run was faster or slower than calibrated, e.g. on a
    loaded machine): the attempt says nothing about the tool and is made again."""


def with_timing_retries(attempt, label, tries=4):
    """Runs `attempt(k)` (k = 0, 1, ...) until it completes without a Timing exception; each attempt
    recalibrates. A Timing exception on the last try is a failure."""
    for k in range(tries):
        try:
            attempt(k)
            return
        except Timing as t:
            print("note: %s (attempt %d of %d)" % (t, k + 1, tries), flush=True)
    check(False, label + ": no attempt could stop the run where intended (see the notes above)")


def interrupted_runs(args, reference, label, stops, ranks=0, resume_ranks=0):
    """Runs `args` and stops it by a signal several times, resuming each time, then resumes it to the
    end: the file must equal `reference`. A stop is (signal, seconds), or (signal, None): once the run
    has written rows for more than 1.3 s (the journal records rows every second)."""
    out = args[args.index("--output") + 1]
    for k, (sig, wait) in enumerate(stops):
        command = tool_command(args + ["--progress"] + (["--resume"] if k > 0 else []), ranks if k == 0 else resume_ranks)
        p = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, universal_newlines=True,
                             start_new_session=True, env=tool_environment(ranks if k == 0 else resume_ranks))
        start = time.time()
        err = ""
        first = None
        while p.poll() is None:
            r, _, _ = select.select([p.stderr], [], [], 0.02)
            if r:
                line = p.stderr.readline()
                err += line
                done = re.match(r"^%s: (\d+)/(\d+) rows" % PROGRAM, line)
                if done and first is None:
                    first = int(done.group(1))
                if wait is None and done and int(done.group(1)) > first and time.time() - start > 1.3:
                    break
            if wait is not None and time.time() - start >= wait:
                break
        if p.poll() is not None:
            raise Timing("%s: the run ended before it was stopped (the machine was faster than calibrated):\n%s"
                         % (label, err))
        if ranks > 0 and k == 0:
            # stop one rank (a child of mpirun); mpirun then ends the others
            children = subprocess.run(["pgrep", "-P", str(p.pid)], stdout=subprocess.PIPE,
                                      universal_newlines=True).stdout.split()
            check(len(children) >= 1, label + ": no rank found")
            os.kill(int(children[-1]), sig)
        else:
            os.killpg(p.pid, sig)
        p.communicate(timeout=120)
        if p.returncode == 0:
            # it ended between the last poll and the signal: then it must have completed its file
            if not check(os.path.exists(out), label + ": a run that ended with code 0 left no file"):
                return
            same_file(reference, out, label + " (run completed before its stop)")
            raise Timing(label + ": a stopped run had completed its file before the signal landed")
    if os.path.exists(out):
        # a stop that landed after the run had completed its file (renamed it into place) but before it
        # exited: the file must then be the complete one; this attempt tested no resume
        same_file(reference, out, label + " (run completed before its stop)")
        raise Timing(label + ": the last stopped run had completed its file before the signal landed")
    _, err = run(args + ["--resume", "--progress"], ranks=resume_ranks)
    note = re.search(r"resuming: (\d+) of (\d+)", err)
    check(note is not None, label + ": the last resume did not say what it found:\n" + err)
    same_file(reference, out, label)
    leftovers = [f for f in os.listdir(os.path.dirname(out)) if f.startswith(os.path.basename(out) + ".part")]
    check(not leftovers, label + ": partial files left: %s" % leftovers)
    if note is not None and not 0 < int(note.group(1)) < int(note.group(2)):
        # the file was checked, but this attempt did not test a resume in the middle of the rows
        raise Timing(label + ": the last resume found no row or all rows done (timing):\n" + err)


def rows_per_second(mesh_file, extra=()):
    """Rows per second of one thread on this machine, with the options `extra` (the interrupted runs must
    last a few seconds whatever the speed of the machine or of the build, and a distance limit makes rows
    cheaper)."""
    out = work("calibration.h5")
    fresh("calibration.h5")
    start = time.time()
    run([mesh_file, "--sources", "0:40", "--output", out, "--threads", 1] + list(extra))
    return 40 / (time.time() - start)


def test_resume():
    """Stopped by SIGKILL / SIGTERM / SIGINT at various moments (also at the very start), then
    resumed: the same file as an uninterrupted run (dense float64, sparse float32)."""
    m = mesh("elephant.off")
    for extra, label in [([], "dense"), (["--max-distance", "0.5", "--float32"], "sparse"),
                         (["--max-distance", "0.3", "--polar"], "polar")]:
        def attempt(k):
            # about 5 s of rows on one thread (more after a failed attempt): two stops after ~1.4 s each,
            # the rest for the last run
            rows = min(2775, max(60, int((5 + 2 * k) * rows_per_second(m, extra))))
            ref, out = work("ref_%s.h5" % label), work("resumed_%s.h5" % label)
            fresh("ref_%s.h5" % label, "resumed_%s.h5" % label)
            run([m, "--sources", "0:%d" % rows, "--output", ref, "--threads", 2] + extra)
            # at the very start (while the files are made), within the first second (nothing recorded
            # yet), then twice in the middle of the rows
            stops = [(signal.SIGKILL, 0.0), (signal.SIGKILL, 0.1), (signal.SIGTERM, 0.5), (signal.SIGKILL, None),
                     (signal.SIGINT, None)]
            interrupted_runs([m, "--sources", "0:%d" % rows, "--output", out, "--threads", 1] + extra, ref,
                             "resume " + label, stops)
        with_timing_retries(attempt, "resume " + label)


def test_resume_mpi():
    """An MPI run whose rank is killed, resumed with another number of ranks: the same file."""
    if not A.mpirun:
        print("SKIP: built without MPI")
        return
    m = mesh("elephant.off")
    for extra, label in [([], "dense"), (["--max-distance", "0.5"], "sparse"), (["--max-distance", "0.3", "--polar"], "polar")]:
        def attempt(k):
            # about 2 s of rows for two ranks of one thread (more after a failed attempt)
            rows = min(2775, max(60, int((4 + 2 * k) * rows_per_second(m, extra))))
            ref, out = work("ref_mpi_%s.h5" % label), work("resumed_mpi_%s.h5" % label)
            fresh("ref_mpi_%s.h5" % label, "resumed_mpi_%s.h5" % label)
            run([m, "--sources", "0:%d" % rows, "--output", ref, "--threads", 2] + extra)
            interrupted_runs([m, "--sources", "0:%d" % rows, "--output", out, "--threads", 1] + extra, ref,
                             "resume mpi " + label, [(signal.SIGKILL, None)], ranks=2, resume_ranks=3)
        with_timing_retries(attempt, "resume mpi " + label)


def expect_error(args, label, output=None, ranks=0):
    """Exit code 2, one line 'vtp_distance_matrix: error: ...', and no output file. (Under MPI, only
    the error line is ours: mpirun adds its own report of a process that ended with a non-zero code.)"""
    _, err = run(args, expect=2, ranks=ranks)
    lines = err.splitlines()
    if ranks > 0:
        lines = [l for l in lines if l.startswith(PROGRAM)]
    check(len(lines) == 1 and lines[0].startswith(PROGRAM + ": error: "), "%s: one error line expected, got:\n%s"
          % (label, err))
    if output is not None:
        check(not os.path.exists(output), label + ": output created")
    return err


def test_bad_input():
    """Bad arguments, meshes and source lists: one line, exit code 2, nothing written."""
    m = mesh("sphere.off")
    out = work("bad.h5")
    fresh("bad.h5")
    ed = A.cli_data
    with open(work("sources_ok.txt"), "w") as f:
        f.write("# a comment\n3, 4\n5\t6  # another\n")
    with open(work("sources_empty.txt"), "w") as f:
        f.write("# nothing\n\n")
    with open(work("sources_bad.txt"), "w") as f:
        f.write("1 2\n3 x 4\n")
    with open(work("sources_range.txt"), "w") as f:
        f.write("1 2 162\n")
    os.makedirs(work("a_folder.h5"), exist_ok=True)
    cases = [
        ([], "no arguments"),
        ([m, "--output", out], "no --sources"),
        ([m, "--sources", "all"], "no --output"),
        ([m, "--sources", "all", "--output", out, "--frobnicate"], "unknown option"),
        ([m, "--sources", "all", "--output", out, "--float32=1"], "value for a flag"),
        ([m, m, "--sources", "all", "--output", out], "two meshes"),
        ([work("missing.off"), "--sources", "all", "--output", out], "missing mesh"),
        ([os.path.join(ed, "garbage.off"), "--sources", "all", "--output", out], "garbage mesh"),
        ([os.path.join(ed, "truncated.off"), "--sources", "all", "--output", out], "truncated mesh"),
        ([os.path.join(ed, "degenerate_only.off"), "--sources", "all", "--output", out], "no face left"),
        ([work("sources_ok.txt"), "--sources", "all", "--output", out], "mesh with unknown extension"),
        ([m, "--sources", "5:5", "--output", out], "empty range"),
        ([m, "--sources", "0:163", "--output", out], "range beyond the mesh"),
        ([m, "--sources", "9:3", "--output", out], "reversed range"),
        ([m, "--sources", "1:2:3", "--output", out], "bad range"),
        ([m, "--sources", "1,,2", "--output", out], "empty item"),
        ([m, "--sources", "1,2,", "--output", out], "trailing comma"),
        ([m, "--sources", "-1", "--output", out], "negative index"),
        ([m, "--sources", "162", "--output", out], "index out of range"),
        ([m, "--sources", "99999999999999999999999", "--output", out], "huge index"),
        ([m, "--sources", work("no_such_list.txt"), "--output", out], "missing source file"),
        ([m, "--sources", work("sources_empty.txt"), "--output", out], "empty source file"),
        ([m, "--sources", work("sources_bad.txt"), "--output", out], "bad token in source file"),
        ([m, "--sources", work("sources_range.txt"), "--output", out], "out of range in source file"),
        ([m, "--sources", A.work, "--output", out], "folder as source file"),
        ([m, "--sources", "all", "--output", out, "--lambda", "4"], "--lambda with vtp"),
        ([m, "--sources", "all", "--output", out, "--method", "avtp", "--lambda", "0"], "--lambda 0"),
        ([m, "--sources", "all", "--output", out, "--method", "pvtp"], "unknown method"),
        ([m, "--sources", "all", "--output", out, "--max-distance", "-1"], "negative limit"),
        ([m, "--sources", "all", "--output", out, "--max-distance", "nan"], "NaN limit"),
        ([m, "--sources", "all", "--output", out, "--max-distance", "1e999"], "overflowing limit"),
        ([m, "--sources", "all", "--output", out, "--threads", "0"], "zero threads"),
        ([m, "--sources", "all", "--output", out, "--threads", "two"], "bad thread count"),
        ([m, "--sources", "all", "--output", out, "--resume", "--force"], "--resume and --force"),
        ([m, "--sources", "all", "--output", work("no_such_folder/out.h5")], "output in a missing folder"),
        ([m, "--sources", "all", "--output", work("a_folder.h5")], "output is a folder"),
    ]
    for args, label in cases:
        expect_error(args, label, out)
    check(not [f for f in os.listdir(A.work) if f.startswith("bad.h5")], "partial files left by bad input")
    # a file of sources that is fine
    run([m, "--sources", work("sources_ok.txt"), "--output", out])
    s, _ = read_dense(out)
    check(list(s) == [3, 4, 5, 6], "sources read from a file: %s" % list(s))
    if A.mpirun:
        expect_error([m, "--sources", "0:999", "--output", out + "2"], "bad sources under MPI", out + "2", ranks=2)


def test_protect_output():
    """An existing complete output is never damaged: not overwritten without --force, not by a bad
    run, not by a --resume with other arguments or another mesh; a partial run is not discarded
    silently either."""
    m = mesh("elephant_395.off")
    out = work("kept.h5")
    fresh("kept.h5")
    base = [m, "--sources", "0:40", "--output", out]
    run(base)
    h = file_hash(out)
    expect_error(base, "existing output")
    expect_error(base + ["--resume", "--method", "avtp"], "resume with another method")
    expect_error(base + ["--resume", "--float32"], "resume with float32")
    expect_error(base + ["--resume", "--max-distance", "0.1"], "resume with a limit")
    expect_error([mesh("elephant-with-holes_565.off"), "--sources", "0:40", "--output", out, "--resume"],
                 "resume with another mesh")
    expect_error([m, "--sources", "0:41", "--output", out, "--resume"], "resume with other sources")
    expect_error([m, "--sources", "0:4000", "--output", out, "--force"], "bad sources with --force")
    _, err = run(base + ["--resume"])
    check("already complete" in err, "resume of a complete output says so: " + err)
    check(file_hash(out) == h, "the complete output was changed")
    check(not [f for f in os.listdir(A.work) if f.startswith("kept.h5.")], "partial files next to kept.h5")
    # --force replaces it, by a complete file of the new arguments
    run([m, "--sources", "5,6", "--output", out, "--force", "--float32"])
    s, d = read_dense(out)
    check(list(s) == [5, 6] and d.dtype == np.float32, "--force wrote the new output")

    # a partial run is neither overwritten, nor resumed with other arguments, nor run twice at once
    part_out = work("partial.h5")
    fresh("partial.h5")
    m = mesh("elephant.off")
    # Deterministic whatever the speed of the machine: the run is frozen (SIGSTOP) as soon as it reports its
    # first rows written, so it still holds its output while the second run tries it, then it is killed.
    args = [m, "--sources", "all", "--output", part_out, "--threads", 1]
    p = subprocess.Popen(tool_command(args + ["--progress"]), stderr=subprocess.PIPE, universal_newlines=True)
    while True:
        line = p.stderr.readline()
        if not line or re.match(r"^%s: [1-9][0-9]*/" % PROGRAM, line):
            break
    os.kill(p.pid, signal.SIGSTOP)
    check(line and not re.match(r"^%s: (\d+)/\1 " % PROGRAM, line), "the partial run ended before it was frozen: "
          + line)
    err = expect_error(args + ["--resume"], "a second run on the same output")
    check("another run is writing" in err, "the second run says why: " + err)
    check(p.poll() is None, "the frozen run ended")
    p.kill()
    p.communicate()
    journal = part_out + ".part.journal"
    check(os.path.exists(journal), "a killed run leaves its journal")
    h = file_hash(journal)
    err = expect_error(args, "partial run without --resume")
    check("--resume" in err, "the message says how to continue: " + err)
    expect_error(args[:-2] + ["--resume", "--method", "avtp"], "resume a partial run with another method")
    check(file_hash(journal) == h, "the journal of the partial run was changed")
    run([m, "--sources", "0:5", "--output", part_out, "--force", "--quiet"])
    check(os.path.exists(part_out) and not [f for f in os.listdir(A.work) if f.startswith("partial.h5.")],
          "--force discarded the partial run and finished")


def test_full_disk():
    """A write that fails (a full disk, simulated with a file size limit) is one error line and exit
    code 2; the run then resumes to the same file."""
    m = mesh("elephant.off")
    ref, out = work("ref_disk.h5"), work("disk.h5")
    fresh("ref_disk.h5", "disk.h5")
    args = ["--sources", "0:200", "--max-distance", "0.6", "--threads", 2]
    run([m, "--output", ref] + args)
    _, err = run([m, "--output", out] + args, expect=2, limit_file_size=200000)
    lines = err.splitlines()
    check(len(lines) == 1 and lines[0].startswith(PROGRAM + ": error: cannot write"), "one error line: " + err)
    check(not os.path.exists(out), "no output after a failed write")
    _, err = run([m, "--output", out, "--resume"] + args)
    same_file(ref, out, "resumed after a failed write")
    # dense: the file cannot even be made
    _, err = run([m, "--output", work("disk_dense.h5"), "--sources", "0:200"], expect=2, limit_file_size=200000)
    check(len(err.splitlines()) == 1 and not os.path.exists(work("disk_dense.h5")), "dense: " + err)


def test_progress():
    """--progress: lines 'N/M rows (P%), R rows/s, T left', the last one N/N; nothing with --quiet
    or on a non-terminal by default; on a terminal, one line rewritten in place."""
    m = mesh("elephant_395.off")
    pattern = r"^%s: \d+/395 rows \(\d+\.\d%%\), [0-9.]+ rows/s, (\d+ s|\d+ min \d\d s|\?)( left)?$" % PROGRAM
    for flags, expect_lines in [(["--progress"], True), (["--quiet"], False), ([], False)]:
        out = work("progress.h5")
        fresh("progress.h5")
        _, err = run([m, "--sources", "all", "--output", out] + flags)
        lines = err.splitlines()
        if expect_lines:
            check(len(lines) >= 1 and all(re.match(pattern, l) for l in lines), "progress lines:\n" + err)
            check(lines[-1].startswith(PROGRAM + ": 395/395 rows (100.0%)"), "last progress line: " + lines[-1])
        else:
            check(err == "", "no progress expected with %s, got:\n%s" % (flags, err))
    # on a terminal (default on): carriage returns, one final newline
    fresh("progress.h5")
    master, slave = pty.openpty()
    p = subprocess.Popen(tool_command([m, "--sources", "all", "--output", work("progress.h5")]),
                         stdout=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    text = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:
            break
        if not chunk:
            break
        text += chunk
    p.wait()
    os.close(master)
    text = text.decode()
    check(p.returncode == 0 and text.startswith("\r" + PROGRAM) and text.endswith("\n") and text.count("\n") == 1,
          "terminal progress: %r" % text)


def read_polar(path):
    """(sources, rho CSR, theta data) of a --polar file; checks that /angles shares the indices of /distances."""
    with h5py.File(path, "r") as f:
        g, a = f["distances"], f["angles"]
        check(a["indices"].id == g["indices"].id and a["indptr"].id == g["indptr"].id,
              "/angles/indices and /angles/indptr are the datasets of /distances")
        check(tuple(a.attrs["shape"]) == tuple(g.attrs["shape"]), "/angles@shape")
        check(int(f.attrs["polar"]) == 1, "root attribute polar")
        check(a["data"].dtype == g["data"].dtype and a["data"].shape == g["data"].shape, "/angles/data")
        shape = tuple(int(x) for x in g.attrs["shape"])
        rho = scipy.sparse.csr_matrix((g["data"][:], g["indices"][:], g["indptr"][:]), shape=shape)
        return f["sources"][:], rho, a["data"][:]


def flat_grid_off(path, n=16, seed=4):
    """A jittered triangulated square in the plane z = 0 (convex: geodesics are straight)."""
    rng = np.random.default_rng(seed)
    xs, ys = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n), indexing="ij")
    V = np.stack([xs.ravel(), ys.ravel(), np.zeros(n * n)], axis=1)
    inner = (xs.ravel() > 0) & (xs.ravel() < 1) & (ys.ravel() > 0) & (ys.ravel() < 1)
    V[inner, :2] += rng.uniform(-0.3, 0.3, (inner.sum(), 2)) / n
    F = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
            F += [[a, b, c], [a, c, d]]
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        for p in V:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in F:
            f.write("3 %d %d %d\n" % tuple(t))
    return V


def test_polar():
    """--max-distance R --polar: rho and the vertices are those of the distance rows of the same run without
    --polar (which equal single runs of vtp_geodesics, test rows_single_source), bitwise, on a mesh with
    boundaries and on a repaired one; theta in [0, 2 pi), 0 at the source; on the plane, theta is the Euclidean
    angle up to the reference (angle differences to 1e-12); float32 rounds both; bad combinations."""
    for name, folder, sources, radius in [("elephant-with-holes.off", A.data, "0,17,1000,2797,1500,5", "0.3"),
                                          ("nonmanifold_vertex.off", A.cli_data, "all", "inf")]:
        polar, dist = work("polar.h5"), work("dist.h5")
        fresh("polar.h5", "dist.h5")
        run([os.path.join(folder, name), "--sources", sources, "--output", polar, "--threads", 2,
             "--max-distance", radius, "--polar"])
        run([os.path.join(folder, name), "--sources", sources, "--output", dist, "--threads", 2,
             "--max-distance", radius])
        s, rho, theta = read_polar(polar)
        s2, d = read_csr(dist)
        check(np.array_equal(s, s2), name + ": sources")
        check(np.array_equal(rho.indptr, d.indptr) and np.array_equal(rho.indices, d.indices)
              and bitwise_equal(rho.data, d.data), name + ": rho and the vertices are those of the distance rows")
        check(((theta >= 0) & (theta < 2 * np.pi)).all(), name + ": theta in [0, 2 pi)")
        for i, v in enumerate(s):
            row = slice(rho.indptr[i], rho.indptr[i + 1])
            k = np.flatnonzero(rho.indices[row] == v)
            check(k.size == 1 and rho.data[row][k[0]] == 0 and theta[row][k[0]] == 0,
                  "%s: row %d has its source at rho 0, theta 0" % (name, i))
    V = flat_grid_off(work("plane.off"))
    out = work("plane.h5")
    fresh("plane.h5")
    run([work("plane.off"), "--sources", "0:256", "--output", out, "--max-distance", "0.35", "--polar"])
    s, rho, theta = read_polar(out)
    worst = [0.0, 0.0]  # sources inside, on the border
    for i, c in enumerate(s):
        row = slice(rho.indptr[i], rho.indptr[i + 1])
        idx = rho.indices[row]
        e = np.hypot(V[idx, 0] - V[c, 0], V[idx, 1] - V[c, 1])
        check(np.abs(rho.data[row] - e).max() < 1e-12, "plane: rho of row %d is Euclidean" % i)
        corner = (V[c, 0] in (0, 1)) and (V[c, 1] in (0, 1))
        far = e > 1e-9
        if corner or far.sum() < 2:
            continue  # at a corner of the square the angles are scaled by pi / (pi / 2)
        phi = np.arctan2(V[idx, 1] - V[c, 1], V[idx, 0] - V[c, 0])[far]
        t = theta[row][far]
        gap = np.remainder((t - t[0]) - (phi - phi[0]) + np.pi, 2 * np.pi) - np.pi
        border = V[c, 0] in (0, 1) or V[c, 1] in (0, 1)
        worst[border] = max(worst[border], np.abs(gap).max())
    # a geodesic that grazes a vertex taken for a pseudo-source (a border vertex; or, on this grid, source 148 to
    # vertex 136, nearly through an interior vertex) goes on from that vertex, whose turning angle the log map
    # keeps as a float (1e-7 rad, doc/VTP_geodesics/log_map.txt): 4.8e-7 there, 1e-16 elsewhere
    check(worst[0] < 1e-6 and worst[1] < 1e-6,
          "plane: theta is the Euclidean angle up to the reference (worst %g inside, %g on the border)" % tuple(worst))
    out32 = work("plane32.h5")
    fresh("plane32.h5")
    run([work("plane.off"), "--sources", "0:256", "--output", out32, "--max-distance", "0.35", "--polar", "--float32"])
    s32, rho32, theta32 = read_polar(out32)
    check(rho32.dtype == np.float32 and bitwise_equal(rho32.data, rho.data.astype(np.float32))
          and bitwise_equal(theta32, theta.astype(np.float32)), "float32: rho and theta rounded")
    m = mesh("sphere.off")
    expect_error([m, "--sources", "0:3", "--output", work("bad.h5"), "--polar"], "--polar without --max-distance",
                 work("bad.h5"))
    expect_error([m, "--sources", "0:3", "--output", work("bad.h5"), "--polar", "--max-distance", "1", "--method",
                  "avtp"], "--polar with avtp", work("bad.h5"))
    # a polar partial run is not resumed as a distance run
    fresh("plane.h5")
    run([work("plane.off"), "--sources", "0:256", "--output", out, "--max-distance", "0.35", "--polar"])
    err = expect_error([work("plane.off"), "--sources", "0:256", "--output", out, "--max-distance", "0.35",
                        "--resume"], "a polar file resumed without --polar")
    check("polar" in err, "the error names --polar: " + err)


def test_help():
    out, err = run(["--help"])
    check("--sources" in out and "--max-distance" in out and "--polar" in out and err == "", "help text")


def main():
    global A
    parser = argparse.ArgumentParser()
    parser.add_argument("name")
    parser.add_argument("--tool", required=True)
    parser.add_argument("--geodesics", default="")
    parser.add_argument("--data", required=True)
    parser.add_argument("--cli-data", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--mpirun", default="")
    A = parser.parse_args()
    A.work = os.path.join(A.work, A.name)
    shutil.rmtree(A.work, ignore_errors=True)
    os.makedirs(A.work)
    test = globals().get("test_" + A.name)
    if test is None:
        print("unknown test " + A.name)
        return 2
    if A.name == "rows_single_source" and not A.geodesics:
        print("SKIP: vtp_geodesics is not built")
        return 0
    test()
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    shutil.rmtree(A.work, ignore_errors=True)
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
