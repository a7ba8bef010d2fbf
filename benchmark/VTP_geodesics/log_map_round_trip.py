#!/usr/bin/env python3
"""exp(log v) = v: for every vertex whose geodesic turns at no vertex (via -1 in the log map: reached, not a
source), the straightest walk from the source at theta(v) for rho(v), trace(c, log[v] / rho[v], rho[v]),
ends at v. All of them, from each source given (issue 46).

    PYTHONPATH=build/python /usr/bin/python3 benchmark/VTP_geodesics/log_map_round_trip.py MESH \\
        [--sources 0,5000] [--every K] [--paths]

--every K: every K-th vertex as a source as well (0: none). --paths: also check, per source, that via is -1
exactly where the geodesic path traced back (solver.path) passes through no vertex (one run per vertex: slow on
large meshes). Prints one line per source: the vertices of the set, how many walks end within 1e-9 of the
largest distance from v, the worst end (relative to the largest distance); then the totals. Exit code 1 if a
walk ends farther than 1e-9 of the largest distance (or, with --paths, if via and a path disagree).
"""

import argparse
import sys
import warnings

import numpy as np

import vtp_geodesics


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("--sources", default="0", help="source vertices, comma-separated (default: 0)")
    parser.add_argument("--every", type=int, default=0, help="also every K-th vertex as a source")
    parser.add_argument("--paths", action="store_true", help="check via against the traced paths")
    args = parser.parse_args()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        V, F = vtp_geodesics.read_mesh(args.mesh)
    for w in caught:
        print("# " + str(w.message))
    s = vtp_geodesics.Solver(V, F)
    sources = [int(c) for c in args.sources.split(",") if c]
    if args.every > 0:
        sources += [c for c in range(0, V.shape[0], args.every) if c not in sources]
    print("# %s: %d vertices, %d faces, %d source(s)" % (args.mesh, V.shape[0], F.shape[0], len(sources)))
    total = within = disagree = 0
    worst, worst_at = 0., None
    for c in sources:
        x, via = s.log_map(c, return_via=True)
        rho = np.linalg.norm(x, axis=1)
        reached = np.isfinite(rho)
        largest = rho[reached].max()
        ends = np.flatnonzero((via == -1) & reached & (rho > 0.))
        errors = np.zeros(0)
        if ends.size:
            paths, _, _ = s.trace(np.full(ends.size, c), x[ends] / rho[ends, None], rho[ends])
            errors = np.array([np.linalg.norm(q[-1] - V[v]) for q, v in zip(paths, ends)]) / largest
        ok = int((errors <= 1e-9).sum())
        line = "source %d: %d reached, %d with via -1, %d within 1e-9, worst %.3g" % (
            c, int(reached.sum()) - 1, ends.size, ok, errors.max() if errors.size else 0.)
        if args.paths:
            wrong = 0
            for v in np.flatnonzero(reached & (rho > 0.)):
                through = (s.path(int(v), sources=c, return_locations=True)[2][1:-1] > 1. - 1e-12).any()
                wrong += int((via[v] == -1) == through)
            line += ", via and the path disagree at %d" % wrong
            disagree += wrong
        print(line)
        total += ends.size
        within += ok
        if errors.size and errors.max() > worst:
            worst, worst_at = errors.max(), (c, int(ends[errors.argmax()]))
    print("total: %d vertices with via -1, %d within 1e-9 of the largest distance, worst %.3g%s" % (
        total, within, worst, " (source %d, vertex %d)" % worst_at if worst_at else ""))
    return 0 if within == total and disagree == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
