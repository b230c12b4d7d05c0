#!/usr/bin/env python3
"""A peer for bench/boolean_bench.py: manifold3d's Boolean (PyPI manifold3d), one process.

usage: manifold_boolean.py A B union|intersection|difference OUT.obj [--threads N]
       manifold_boolean.py --csg TREE.csg OUT.obj [--threads N]

A and B (OBJ or OFF, polygons fanned) are loaded with numpy into manifold3d.Mesh64 (doubles);
a CSG tree is the OpenSCAD subset QuickCSG's trees use: union() / intersection() /
difference() { ... } over import(file="NAME"), names relative to the tree's folder.
The result is written as an OBJ ("v" with 17 significant digits, "f"). --threads N keeps
the process (manifold's TBB workers) on N of the allowed cores (default 1).

Prints one JSON line: {"ok": true, "seconds": the Boolean alone, "triangles", "volume"
(float), "peak_rss_mb" (this process's own, getrusage)}. Exit status 0 done; 1 an operand
manifold refuses (not an oriented 2-manifold) or another failure, "failed: ..." on stderr;
2 a bad command line or an unreadable file.
"""
import json
import os
import re
import resource
import sys
import time
from pathlib import Path

import numpy as np

USAGE = __doc__.split("\n\n")[1]


def fail(status, message):
    print(message, file=sys.stderr)
    print(json.dumps({"ok": False, "error": message}))
    sys.exit(status)


def fan(faces):
    """Triangles (k x 3) of polygons given as index lists."""
    return np.array([(f[0], f[i], f[i + 1]) for f in faces for i in range(1, len(f) - 1)], dtype=np.uint64)


def load(file):
    """(vertices n x 3 float64, triangles m x 3 uint64) of an OBJ or OFF file."""
    text = Path(file).read_text(encoding="utf-8", errors="replace")
    lines = [w for w in (line.split("#", 1)[0].split() for line in text.splitlines()) if w]
    if Path(file).suffix.lower() == ".off":
        head = lines[0][1:] if len(lines[0]) > 1 else lines[1]
        first = 1 if len(lines[0]) > 1 else 2
        nv, nf = int(head[0]), int(head[1])
        vertices = np.array([w[:3] for w in lines[first:first + nv]], dtype=np.float64)
        faces = [[int(i) for i in w[1:1 + int(w[0])]] for w in lines[first + nv:first + nv + nf]]
    else:
        vertices = np.array([w[1:4] for w in lines if w[0] == "v"], dtype=np.float64)
        faces = [[int(i.split("/", 1)[0]) - 1 for i in w[1:]] for w in lines if w[0] == "f"]
    if all(len(f) == 3 for f in faces):
        return vertices.reshape(-1, 3), np.array(faces, dtype=np.uint64).reshape(-1, 3)
    return vertices.reshape(-1, 3), fan(faces)


def operand(file):
    import manifold3d as m3d  # imported by main, after the affinity is set
    try:
        vertices, triangles = load(file)
    except (OSError, ValueError, IndexError) as e:
        fail(2, f"cannot read {file}: {e}")
    solid = m3d.Manifold(m3d.Mesh64(vert_properties=np.ascontiguousarray(vertices), tri_verts=triangles))
    if solid.status() != m3d.Error.NoError:
        fail(1, f"failed: manifold refuses {Path(file).name}: {solid.status().name}")
    return solid


def read_tree(file):
    """The tree as nested (op, [children]) with file names as leaves."""
    tokens = re.findall(r'(union|intersection|difference)\s*\(\s*\)\s*\{|import\s*\(\s*file\s*=\s*"([^"]+)"\s*\)\s*;'
                        r'|(\})', Path(file).read_text(encoding="utf-8"))
    stack = [("group", [])]
    for op, name, close in tokens:
        if op:
            stack.append((op, []))
        elif name:
            stack[-1][1].append(str(Path(file).parent / name))
        elif close and len(stack) > 1:
            node = stack.pop()
            stack[-1][1].append(node)
    if len(stack) != 1 or len(stack[0][1]) != 1:
        raise ValueError("unbalanced braces or more than one top-level node")
    return stack[0][1][0]


def leaves(node):
    return [node] if isinstance(node, str) else [f for c in node[1] for f in leaves(c)]


def evaluate(node, solids, combine):
    if isinstance(node, str):
        return solids[node]
    op, children = node
    return combine(op, [evaluate(c, solids, combine) for c in children])


def main(argv):
    args, threads = list(argv), 1
    if "--threads" in args:
        i = args.index("--threads")
        if i + 1 >= len(args) or not re.fullmatch(r"[1-9][0-9]{0,3}", args[i + 1]):
            fail(2, USAGE)
        threads = int(args.pop(i + 1))
        args.pop(i)
    csg = args[:1] == ["--csg"]
    if (csg and len(args) != 3) or (not csg and (len(args) != 4 or args[2] not in ("union", "intersection",
                                                                                    "difference"))):
        fail(2, USAGE)
    allowed = sorted(os.sched_getaffinity(0))
    os.sched_setaffinity(0, allowed[:threads])  # before TBB starts: it sizes its pool from this
    try:
        import manifold3d as m3d
    except ImportError as e:
        fail(1, f"failed: no manifold3d for {sys.executable} ({e})")
    ops = {"union": m3d.OpType.Add, "intersection": m3d.OpType.Intersect, "difference": m3d.OpType.Subtract}

    def combine(op, solids):
        return m3d.Manifold.batch_boolean(solids, ops[op])

    if csg:
        try:
            tree = read_tree(args[1])
        except (OSError, ValueError) as e:
            fail(2, f"cannot read {args[1]}: {e}")
        solids = {f: operand(f) for f in leaves(tree)}
        start = time.perf_counter()
        result = evaluate(tree, solids, combine)
    else:
        a, b = operand(args[0]), operand(args[1])
        start = time.perf_counter()
        result = combine(args[2], [a, b])
    result.num_tri()  # manifold evaluates lazily: force the Boolean inside the timed part
    seconds = time.perf_counter() - start
    mesh = result.to_mesh64()
    vertices, triangles = np.asarray(mesh.vert_properties)[:, :3], np.asarray(mesh.tri_verts)
    try:
        with open(args[-1], "w", encoding="utf-8") as f:
            np.savetxt(f, vertices, fmt="v %.17g %.17g %.17g")
            np.savetxt(f, triangles + 1, fmt="f %d %d %d")
    except OSError as e:
        fail(2, f"cannot write {args[-1]}: {e.strerror}")
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # Linux: kilobytes
    print(json.dumps({"ok": True, "seconds": round(seconds, 6), "triangles": int(len(triangles)),
                      "volume": result.volume(), "peak_rss_mb": peak_mb}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
