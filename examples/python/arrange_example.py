"""Two crossing cubes: find where they intersect, then cut them into an arrangement.

    pip install .                      # from the repository root
    python examples/python/arrange_example.py [out.off]
"""
import sys

import numpy as np
import tritri


def cube(lo, hi):
    """Closed axis-aligned box: 8 vertices (index 4x + 2y + z), 12 outward triangles."""
    V = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])], float)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return V, np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))])


V1, F1 = cube((0, 0, 0), (2, 2, 2))
V2, F2 = cube((1, 1, 1), (3, 3, 3))

# Exact classification of every pair of crossing triangles.
pairs, results = tritri.intersections(V1, F1, V2, F2)
print(f"{len(pairs)} intersecting triangle pairs; the first: {pairs[0].tolist()} {results[0]}")

# One soup with labels 0 and 1, cut along all intersections.
V = np.vstack([V1, V2])
F = np.vstack([F1, F2 + len(V1)])
labels = np.repeat([0, 1], [len(F1), len(F2)])
out = tritri.arrange(V, F, labels=labels)
s = out["stats"]
print(f"arrangement: {len(out['V'])} vertices, {len(out['F'])} triangles, Euler characteristic {s['euler']}, "
      f"{s['intersecting_pairs']} intersecting pairs, {s['t_total_s'] * 1e3:.1f} ms")
print("all output vertices exactly representable:", bool(out["V_is_exact"].all()))
print("self-intersections left:", len(tritri.self_intersections(out["V"], out["F"])[0]))

if len(sys.argv) > 1:  # the arrangement as OFF
    with open(sys.argv[1], "w") as f:
        f.write(f"OFF\n{len(out['V'])} {len(out['F'])} 0\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in out["V"])
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in out["F"])
