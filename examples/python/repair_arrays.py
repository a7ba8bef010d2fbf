"""Arrays that are not a valid mesh: two triangulated squares touching at one corner (a non-manifold vertex),
a face listed twice and one flipped. Solver(V, F) repairs them as the tool repairs a file, says so in a
UserWarning, and answers on the rows of V; the vertex in no face gets inf.

    PYTHONPATH=build/python python3 examples/python/repair_arrays.py
"""
import warnings

import numpy as np

import vtp_geodesics

# square A: vertices 0-3 in z = 0; square B: vertices 4-6 and A's corner 2, in the plane x = 1
V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
              [1, 2, 0], [1, 2, 1], [1, 1, 1],
              [9, 9, 9]], dtype=float)                    # vertex 7: in no face
F = np.array([[0, 1, 2], [0, 2, 3],                      # A
              [2, 4, 5], [2, 6, 5],                      # B, touching A at vertex 2 only; [2, 6, 5] flipped
              [0, 1, 2]])                                # a duplicate face

try:
    vtp_geodesics.Solver(V, F, repair=False)
except ValueError as e:
    print("repair=False:", e)

with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    solver = vtp_geodesics.Solver(V, F)                    # repair=True is the default
print("warning:", caught[0].message)

print("from vertex 0, copies apart (the default):", np.round(solver.distances(0), 4))
with warnings.catch_warnings():
    warnings.simplefilter("ignore")                        # the same warning again
    joined = vtp_geodesics.Solver(V, F, through_pinches=True)
print("from vertex 0, through the pinch:          ", np.round(joined.distances(0), 4))
print("a path on the caller's indices:", solver.path(3, sources=0, return_locations=True)[1], "(faces of F)")
