# Shared fixtures of the pytest suite of the Python module vtp_geodesics (run by CTest: see CMakeLists.txt).
#
# Environment (set by CTest): PYTHONPATH=<build>/python, VTP_GEODESICS_TOOL=<build>/bin/vtp_geodesics,
# VTP_GEODESICS_TEST_DATA=<source>/test/VTP_geodesics/data.

import os

import numpy as np
import pytest

import vtp_geodesics

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("VTP_GEODESICS_TEST_DATA", os.path.join(HERE, "..", "VTP_geodesics", "data"))


def data_file(name):
    return os.path.join(DATA, name)


def read_tool_text(path):
    # the tool writes the shortest text that reads back as the same double, and "inf"
    with open(path) as f:
        return np.array([float(line) for line in f], dtype=np.float64)


def read_tool_labels(path):
    with open(path) as f:
        return np.array([int(line) for line in f], dtype=np.int64)


def plane_grid(nx, ny, size=1.0, jitter=0.0, seed=1):
    """A triangulated square [0, size]^2 in the plane z = 0 (vertices on a grid, optionally jittered)."""
    rng = np.random.default_rng(seed)
    xs, ys = np.meshgrid(np.linspace(0, size, nx), np.linspace(0, size, ny), indexing="ij")
    V = np.stack([xs.ravel(), ys.ravel(), np.zeros(nx * ny)], axis=1)
    if jitter:
        inner = (xs.ravel() > 0) & (xs.ravel() < size) & (ys.ravel() > 0) & (ys.ravel() < size)
        V[inner, :2] += rng.uniform(-jitter, jitter, (inner.sum(), 2)) * size / nx
    F = []
    for i in range(nx - 1):
        for j in range(ny - 1):
            a, b, c, d = i * ny + j, (i + 1) * ny + j, (i + 1) * ny + j + 1, i * ny + j + 1
            if (i + j) % 2:
                F += [[a, b, c], [a, c, d]]
            else:
                F += [[a, b, d], [b, c, d]]
    return V, np.array(F, dtype=np.int64)


def cylinder(n_around, n_up, radius=1.0, height=2.0):
    """The lateral surface of a prism with a regular n_around-gon section (open at both ends): developable,
    it unrolls onto a strip of width n_around * chord."""
    t = 2 * np.pi * np.arange(n_around) / n_around
    z = np.linspace(0, height, n_up)
    V = np.array([[radius * np.cos(a), radius * np.sin(a), h] for h in z for a in t])
    F = []
    for k in range(n_up - 1):
        for i in range(n_around):
            a, b = k * n_around + i, k * n_around + (i + 1) % n_around
            c, d = a + n_around, b + n_around
            F += [[a, b, d], [a, d, c]]
    return V, np.array(F, dtype=np.int64)


@pytest.fixture(scope="session")
def elephant():
    V, F = vtp_geodesics.read_mesh(data_file("elephant.off"))
    return V, F, vtp_geodesics.Solver(V, F)


@pytest.fixture(scope="session")
def tool():
    path = os.environ.get("VTP_GEODESICS_TOOL")
    if not path or not os.path.exists(path):
        pytest.skip("VTP_GEODESICS_TOOL is not set to the built vtp_geodesics tool")
    return path


def assert_interrupt_stops(call, what):
    """Runs call() (a computation of several seconds), sends Ctrl-C (KeyboardInterrupt) after 0.5 s, and checks
    that it stops within 2 s, leaves no thread behind and nothing computing after it returned."""
    import _thread
    import resource
    import threading
    import time
    threads_before = threading.active_count()
    sent = []

    def interrupt():
        sent.append(time.monotonic())
        _thread.interrupt_main()

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        call()
    stopped = time.monotonic() - sent[0]
    timer.join()
    print("%s stopped %.3f s after the interrupt" % (what, stopped))
    assert stopped < 2.0, "the %s stopped %.2f s after the interrupt" % (what, stopped)
    assert threading.active_count() == threads_before
    # nothing keeps computing after the call returned: the process uses (almost) no processor time
    time.sleep(0.2)
    cpu0 = resource.getrusage(resource.RUSAGE_SELF)
    time.sleep(0.5)
    cpu1 = resource.getrusage(resource.RUSAGE_SELF)
    assert (cpu1.ru_utime - cpu0.ru_utime) + (cpu1.ru_stime - cpu0.ru_stime) < 0.25
