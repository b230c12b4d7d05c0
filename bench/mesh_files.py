"""Exact readers of OFF, OBJ and STL meshes for the bench scripts (bench/render.py).

    from mesh_files import read_mesh, input_faces, sharing, exact_number, float_number

read_mesh(path, number) -> (vertices, faces): vertices as tuples of number(token) (by default
exact_number: a Fraction for a rational N/D, as `arrange --exact` writes, else a float), faces
as tuples of vertex indices (polygons kept; an STL facet has its own three corners). OFF (the
header may carry the counts; colours after a face are ignored), OBJ (`v` and `f` lines; `f a/b/c`
and negative indices), ASCII and binary STL. MeshError when a file cannot be read.

input_faces(paths) and sharing(face_of, corners) decide exactly, on the concatenated inputs,
whether two input triangles share an input edge: vertices with equal coordinates merged (1/2 and
0.5 are equal: Python's numeric tower), two merged vertices in common, or one polygon face.
"""
from fractions import Fraction
from pathlib import Path

READABLE = (".off", ".obj", ".stl")


class MeshError(Exception):
    """A mesh file that cannot be read here (the message names it)."""


def exact_number(token):
    """A coordinate as read for exact comparison: a Fraction for N/D, else a float. Equal values
    compare and hash equal across the two types (Python's numeric tower), e.g. 1/2 and 0.5."""
    return Fraction(token) if "/" in token else float(token)


def float_number(token):
    if "/" in token:
        n, d = token.split("/")
        return int(n) / int(d)  # correctly rounded, also for huge numerators
    return float(token)


def _lines(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words:
                yield words


def read_off(path, number=exact_number):
    lines = _lines(path)
    head = next(lines, None)
    if not head or not head[0].endswith("OFF"):
        raise MeshError(f"{path}: not an OFF file")
    counts = head[1:] or next(lines, [])
    nv, nf = int(counts[0]), int(counts[1])
    vertices = [tuple(number(w) for w in next(lines)[:3]) for _ in range(nv)]
    faces = []
    for _ in range(nf):
        words = next(lines)
        faces.append(tuple(int(w) for w in words[1:1 + int(words[0])]))
    return vertices, faces


def read_obj(path, number=exact_number):
    vertices, faces = [], []
    for words in _lines(path):
        if words[0] == "v":
            vertices.append(tuple(number(w) for w in words[1:4]))
        elif words[0] == "f":
            ids = (int(w.split("/", 1)[0]) for w in words[1:])
            faces.append(tuple(i - 1 if i > 0 else len(vertices) + i for i in ids))
    return vertices, faces


def read_stl(path, number=exact_number):
    """Every facet its own three corners (merging is the caller's)."""
    data = Path(path).read_bytes()
    if len(data) >= 84 and 84 + 50 * int.from_bytes(data[80:84], "little") == len(data):
        import numpy as np
        rec = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
        corners = np.frombuffer(data, rec, offset=84)["v"].astype(float).reshape(-1, 3).tolist()
        vertices = [tuple(c) for c in corners]
    else:
        words = data.decode("ascii", "replace").split()
        vertices = [tuple(number(w) for w in words[i + 1:i + 4])
                    for i, w in enumerate(words) if w == "vertex"]
    return vertices, [(i, i + 1, i + 2) for i in range(0, len(vertices) - 2, 3)]


def read_mesh(path, number=exact_number):
    reader = {".off": read_off, ".obj": read_obj, ".stl": read_stl}.get(Path(path).suffix.lower())
    if reader is None:
        raise MeshError(f"{path}: cannot read {Path(path).suffix} files here "
                          f"(only {', '.join(READABLE)})")
    try:
        return reader(path, number)
    except StopIteration:
        raise MeshError(f"{path}: cannot read the mesh (the file ends early)") from None
    except (OSError, ValueError, IndexError) as e:
        raise MeshError(f"{path}: cannot read the mesh ({e})") from None


def input_faces(paths):
    """(face_of, corners): face_of[s] is the face of input triangle s (the index in the
    concatenated triangle lists, an n-gon giving n - 2 consecutive triangles) and corners[f] the
    frozenset of merged vertex ids of face f, vertices merged when their coordinates are equal."""
    merged, face_of, corners = {}, [], []
    for p in paths:
        vertices, faces = read_mesh(p)
        ids = [merged.setdefault(v, len(merged)) for v in vertices]
        for face in faces:
            if len(face) >= 3:
                face_of += [len(corners)] * (len(face) - 2)
                corners.append(frozenset(ids[i] for i in face))
    return face_of, corners


def sharing(face_of, corners):
    """share(s, t): input triangles s and t share an input edge (two merged vertices, or one
    polygon face)."""
    def share(s, t):
        f, g = face_of[s], face_of[t]
        return f == g or len(corners[f] & corners[g]) >= 2
    return share
