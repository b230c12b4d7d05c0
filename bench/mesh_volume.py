#!/usr/bin/env python3
"""Exact volume and boundary edges of a closed mesh (OBJ, OFF or STL).

usage: bench/mesh_volume.py FILE [--json]

Coordinates are read exactly: a decimal is the double it rounds to (as every tool reads it),
taken at its exact binary value; "N/D" (what `arrange --exact` writes) is that rational.
Vertices with equal coordinates are merged. The volume is the sum over the faces of the
signed volumes of the tetrahedra (origin, a, b, c), polygons fanned from their first corner,
as a fractions.Fraction: positive for a closed mesh oriented outwards, negative inside out.

A boundary edge is an undirected edge (between merged vertices) whose two directions are
not used equally often: an edge of a hole (used once), or one whose faces disagree on the
orientation. A closed, consistently oriented mesh has none; non-manifold edges (used more
than twice) are counted apart and may still be balanced.

Prints the volume as N/D and as a float, the boundary edges, non-manifold edges, faces and
vertices; with --json one object (volume as the string "N/D", volume_float, boundary_edges,
non_manifold_edges, closed, triangles, vertices). Exit status: 0 done, 1 the file cannot be
read as a mesh, 2 a bad command line.

From Python: `from mesh_volume import measure; m = measure(path)`, the same keys with the
volume as a Fraction.
"""
import argparse
import json
import math
import sys
from collections import Counter
from fractions import Fraction

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args, mesh_files
from cli_args import Parser, path  # noqa: E402
from mesh_files import MeshError, read_mesh  # noqa: E402

if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)  # exact volumes run to many thousand digits (Python >= 3.11 caps at 4300)


def exact_ratio(token):
    """(numerator, denominator) of a coordinate token, in lowest terms, denominator > 0."""
    if "/" not in token:
        return float(token).as_integer_ratio()  # exact; ValueError for inf and nan
    n, d = (int(w) for w in token.split("/"))
    if d == 0:
        raise ValueError(f"zero denominator in {token!r}")
    g = math.gcd(n, d) * (1 if d > 0 else -1)
    return n // g, d // g


def homogeneous(coordinates):
    """(X, Y, Z, W) integers with the point (X/W, Y/W, Z/W), W > 0 the least such."""
    ratios = [c if isinstance(c, tuple) else c.as_integer_ratio() for c in coordinates]  # binary STL: floats
    w = math.lcm(*(d for _, d in ratios))
    return tuple(n * (w // d) for n, d in ratios) + (w,)


def pairwise_sum(fractions):
    """Sum of Fractions added in a balanced tree: operands grow together, so the large
    numbers meet only near the root (summing left to right makes every addition large)."""
    items = list(fractions) or [Fraction(0)]
    while len(items) > 1:
        items = [items[i] + items[i + 1] if i + 1 < len(items) else items[i] for i in range(0, len(items), 2)]
    return items[0]


def measure(file):
    """{volume: Fraction, volume_float, boundary_edges, non_manifold_edges, closed, triangles,
    vertices} of a mesh file; MeshError when it cannot be read."""
    try:
        points, faces = read_mesh(file, exact_ratio)
        merged, ids = {}, []
        for p in points:
            ids.append(merged.setdefault(homogeneous(p), len(merged)))
        corners = [tuple(ids[i] for i in face) for face in faces if len(face) >= 3]
    except (ValueError, IndexError, OverflowError, TypeError) as e:
        raise MeshError(f"{file}: cannot read the mesh ({e})") from None
    vertex = list(merged)
    by_denominator = Counter()  # W_a W_b W_c -> sum of det(A, B, C): no Fraction per face
    directed = Counter()
    triangles = 0
    for face in corners:
        xa, ya, za, wa = vertex[face[0]]
        for j in range(1, len(face) - 1):
            xb, yb, zb, wb = vertex[face[j]]
            xc, yc, zc, wc = vertex[face[j + 1]]
            det = xa * (yb * zc - zb * yc) - ya * (xb * zc - zb * xc) + za * (xb * yc - yb * xc)
            if det:
                by_denominator[wa * wb * wc] += det
            triangles += 1
        directed.update(zip(face, face[1:] + face[:1]))
    volume = pairwise_sum(Fraction(n, d) for d, n in by_denominator.items()) / 6
    boundary = non_manifold = 0
    for (u, v), count in directed.items():
        if u == v or (u > v and (v, u) in directed):
            continue  # a degenerate corner, or an edge counted from its other direction
        back = directed.get((v, u), 0)
        boundary += count != back
        non_manifold += count + back > 2
    return {"volume": volume, "volume_float": float(volume), "boundary_edges": boundary,
            "non_manifold_edges": non_manifold, "closed": boundary == 0, "triangles": triangles,
            "vertices": len(vertex)}


def main(argv=None):
    ap = Parser(prog="mesh_volume.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file", type=path, metavar="FILE", help="an OBJ, OFF or STL mesh")
    ap.add_argument("--json", action="store_true", help="print one JSON object")
    args = ap.parse_args(argv)
    try:
        m = measure(args.file)
    except MeshError as e:
        print(f"mesh_volume.py: {e}", file=sys.stderr)
        return 1
    v = m["volume"]
    if args.json:
        print(json.dumps({"file": str(args.file), **m, "volume": f"{v.numerator}/{v.denominator}"}))
    else:
        print(f"volume {v.numerator}/{v.denominator} (~ {m['volume_float']:.17g})\n"
              f"boundary edges {m['boundary_edges']}, non-manifold edges {m['non_manifold_edges']}\n"
              f"triangles {m['triangles']}, vertices {m['vertices']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
