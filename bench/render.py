#!/usr/bin/env python3
"""A picture of one arrangement: the mesh shaded per input file, the intersection curves over it.

usage: bench/render.py INPUT... -o OUT.png [--arrange PATH] [--size PX] [--title TEXT]
           [--timeout SECONDS]

Runs `arrange INPUT... -o TMP.obj --exact --stats` in a temporary folder and draws its output
headless (matplotlib, Agg, orthographic view from elevation 25 and azimuth -60, equal aspect):
every output triangle in the colour of its input file (its label; a region shared by coplanar
triangles of several files gets the mean of their colours), Lambert-shaded from its face normal,
and the intersection curves over it as thick red lines (thinner where they are dense; hidden
parts of sparse curves thin and faint). At most 200000 triangles are drawn (the largest ones of
a larger output); curve edges are never left out.

Intersection curves: an output edge is on a curve iff two of its output triangles come from input
triangles (the column `source` of TMP.obj.provenance.csv: the index in the inputs' concatenated
triangle lists, an n-gon counting n - 2) that do not share an input edge. That is decided
combinatorially and exactly on the inputs, read here (bench/mesh_files.py: OFF, OBJ, ASCII and
binary STL; coordinates as Python floats, or fractions where a file has N/D): vertices with
exactly equal coordinates are merged, and two input triangles share an input edge iff they have two
merged vertices in common (the n - 2 triangles of a polygon face count as that face, whose
triangulation is arrange's business). Other formats (PLY), or input that does not match arrange's
triangle count, give a picture without curves and a warning. Coordinates are converted to floats
only to draw.

Module: render(inputs, png, ...) -> summary; draw_inputs(inputs, png, ...): the inputs alone
(no arrange); curve_edges(), input_faces(): the exact parts. Writes are atomic.

Exit status: 0 written, 1 arrange failed or the picture could not be drawn, 2 bad command line
(an empty or out-of-range value, an option given twice, a missing INPUT or --arrange, an output
name not ending in .png).
"""
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from itertools import combinations
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args, mesh_files
from atomic_write import write_atomic  # noqa: E402
from cli_args import Parser, integer, path, seconds, text  # noqa: E402  (after the line above)
from mesh_files import (READABLE, MeshError, exact_number, float_number,  # noqa: E402,F401
                        input_faces, read_mesh, read_obj, read_off, read_stl, sharing)

REPO_ROOT = Path(__file__).resolve().parent.parent
DEFAULT_ARRANGE = REPO_ROOT / "build" / "bin" / "arrange"
MAX_FACES = 200_000
ELEV, AZIM = 25, -60
# Light, distinct fill colours (no red: the curves are red), one per input file, cycled.
LABEL_COLOURS = ("#8fb8de", "#a8d5a2", "#f2cf8c", "#c3b1e1", "#9fd8d0", "#e3b8c8", "#d9d98c",
                 "#bfbfbf")
CURVE_COLOUR = "#d40000"


class RenderError(Exception):
    """The picture could not be made (the message says why)."""


class ArrangeError(RenderError):
    """arrange failed, timed out or crashed on the inputs."""


def read_provenance(path):
    """(source per output triangle, label tuple per output triangle)."""
    sources, labels = [], []
    with open(path, newline="") as f:
        for number, row in enumerate(csv.DictReader(f)):
            if int(row["triangle"]) != number:
                raise RenderError(f"{path}: row {number + 2} is triangle {row['triangle']}")
            sources.append(int(row["source"]))
            labels.append(tuple(int(x) for x in row["labels"].split()))
    return sources, labels


# ---------------------------------------------------------------------------------------------
# Intersection curves


def curve_edges(triangles, sources, share):
    """The output edges (i, j), i < j, on an intersection curve: two of the triangles around
    the edge come from input triangles that do not share an input edge. triangles: (M, 3)
    vertex indices; sources: M input triangle indices; share(s, t) -> bool."""
    import numpy as np
    tris = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    if len(tris) == 0:
        return []
    edges = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    src = np.tile(np.asarray(sources, dtype=np.int64), 3)
    order = np.lexsort((edges[:, 1], edges[:, 0]))
    edges, src = edges[order], src[order]
    starts = np.flatnonzero(np.r_[True, (edges[1:] != edges[:-1]).any(axis=1)])
    ends = np.r_[starts[1:], len(edges)]
    mixed = np.minimum.reduceat(src, starts) != np.maximum.reduceat(src, starts)
    found, known = [], {}
    for g in np.flatnonzero(mixed):  # only edges between different input triangles
        for pair in combinations(sorted(set(src[starts[g]:ends[g]].tolist())), 2):
            if pair not in known:
                known[pair] = share(*pair)
            if not known[pair]:
                found.append(tuple(edges[starts[g]].tolist()))
                break
    return found


# ---------------------------------------------------------------------------------------------
# Drawing


def label_rgb(labels):
    from matplotlib.colors import to_rgb
    cols = [to_rgb(LABEL_COLOURS[k % len(LABEL_COLOURS)]) for k in labels] or [to_rgb("#bfbfbf")]
    return tuple(sum(c[i] for c in cols) / len(cols) for i in range(3))


def screen_axes(elev, azim):
    """(eye, right, up) unit vectors of the orthographic view."""
    import numpy as np
    e, a = np.radians(elev), np.radians(azim)
    eye = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    right = np.array([-np.sin(a), np.cos(a), 0.0])
    return eye, right, np.cross(eye, right)


def pieces_per_side(P, limit):
    import numpy as np
    longest = np.max(np.linalg.norm(P - np.roll(P, 1, axis=1), axis=2), axis=1)
    return np.clip(np.ceil(longest / limit), 1, 64).astype(int)


def refine(P, rgb, k):
    """Triangles (M, 3, 3) split into k * k similar pieces (k per triangle), so that the
    painter's algorithm of mplot3d (one depth per polygon) sorts small pieces."""
    import numpy as np
    out_p, out_c = [P[k == 1]], [rgb[k == 1]]
    for n in np.unique(k[k > 1]):
        grid = [(i, j) for i in range(n + 1) for j in range(n + 1 - i)]
        at = {g: m for m, g in enumerate(grid)}
        pieces = [(at[i, j], at[i + 1, j], at[i, j + 1]) for i, j in grid if i + j < n]
        pieces += [(at[i + 1, j], at[i + 1, j + 1], at[i, j + 1]) for i, j in grid if i + j < n - 1]
        bary = np.array([(n - i - j, i, j) for i, j in grid]) / n      # (G, 3)
        sel = P[k == n]
        points = np.einsum("gc,mcx->mgx", bary, sel)                    # (m, G, 3)
        out_p.append(points[:, np.array(pieces)].reshape(-1, 3, 3))
        out_c.append(np.repeat(rgb[k == n], len(pieces), axis=0))
    return np.concatenate(out_p), np.concatenate(out_c)


def draw(png, vertices, triangles, rgb, curves=(), size=800, title=None, legend=None,
         max_faces=MAX_FACES, elev=ELEV, azim=AZIM):
    """Writes the picture. vertices (N, 3) floats, triangles (M, 3), rgb (M, 3) base colours,
    curves: vertex index pairs. legend: [(label text, colour)] or None. Returns the number of
    triangles of the mesh drawn (before the split into pieces for depth sorting)."""
    import numpy as np
    from matplotlib.colors import to_rgb
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    V = np.asarray(vertices, dtype=float).reshape(-1, 3)
    T = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    rgb = np.asarray(rgb, dtype=float).reshape(-1, 3)
    C = np.asarray(curves, dtype=np.int64).reshape(-1, 2)
    if len(T) > max_faces:  # the largest triangles: the fewest holes
        P = V[T]
        area = np.linalg.norm(np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]), axis=1)
        keep = np.sort(np.argsort(-area, kind="stable")[:max_faces])
        T, rgb = T[keep], rgb[keep]
    eye, right, up = screen_axes(elev, azim)
    used = V[np.unique(np.concatenate([T.ravel(), C.ravel()]))]
    if len(used) == 0:
        raise ValueError("nothing to draw")
    lo, hi = used.min(axis=0), used.max(axis=0)
    centre, diag = (lo + hi) / 2, float(np.linalg.norm(hi - lo)) or 1.0
    half = max(float((hi - lo).max()) / 2, diag * 1e-9)

    P = V[T]
    normals = np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    normals /= np.where(lengths > 0, lengths, 1)[:, None]
    light = screen_axes(elev + 25, azim + 25)[0]  # above and to the right of the eye
    shade = 0.35 + 0.65 * np.abs(normals @ light)  # two-sided: orientation is not known
    colours = np.clip(rgb * shade[:, None], 0, 1)
    limit, k = diag / 40, pieces_per_side(P, diag / 40)
    while (k ** 2).sum() > max(max_faces, len(P)) * 1.5:
        limit *= 1.5
        k = pieces_per_side(P, limit)
    P, colours = refine(P, colours, k)
    # Zoom so that the model, not its bounding cube, fills the picture.
    rel = used - centre  # centred on the screen, not in space
    centre = centre + right * (np.ptp(rel @ right) / 2 + (rel @ right).min()) \
        + up * (np.ptp(rel @ up) / 2 + (rel @ up).min())
    rel = used - centre
    span = max(np.ptp(rel @ right), np.ptp(rel @ up), diag * 1e-9)
    cube = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * half
    fit = min(np.abs(cube @ right).max() / max(np.abs(rel @ right).max(), 1e-300),
              np.abs(cube @ up).max() / max(np.abs(rel @ up).max(), 1e-300))
    # Curves: ribbons (two triangles per piece) as wide on the screen as a thick line, moved
    # towards the eye by a piece of the mesh, which does not move them on the (orthographic)
    # screen: sorted with the mesh, they are hidden where the mesh lies in front of them.
    # (Poly3DCollection reorders colours when it sorts, not line widths: widths stay equal.)
    segs = V[C]
    per_px = span / (0.85 * size)  # data units per pixel, about
    length = np.hypot((segs[:, 1] - segs[:, 0]) @ right, (segs[:, 1] - segs[:, 0]) @ up).sum()
    # Thick lines, thinner where the curves are dense (they may cover a tenth of the model).
    thick = max(2.0, size / 250)
    width_px = max(0.4, min(thick, 0.1 * (0.85 * size) ** 2 / max(length / per_px, 1e-300)))
    width = width_px * per_px  # data units
    n = np.maximum(np.ceil(np.linalg.norm(segs[:, 1] - segs[:, 0], axis=1) / limit), 1).astype(int)
    frac = np.concatenate([np.arange(m + 1) / m for m in n]) if len(n) else np.zeros(0)
    base = np.repeat(segs, n + 1, axis=0)
    points = base[:, 0] + (base[:, 1] - base[:, 0]) * frac[:, None] + eye * limit
    last = np.cumsum(n + 1) - 1
    start = np.setdiff1d(np.arange(len(points)), last)  # each piece: points[i], points[i + 1]
    a, b = points[start], points[start + 1]
    side = np.cross(eye, b - a)
    side *= (width / 2) / np.maximum(np.linalg.norm(side, axis=1), 1e-300)[:, None]
    ribbons = np.concatenate([np.stack([a + side, a - side, b - side], axis=1),
                              np.stack([a + side, b - side, b + side], axis=1)])
    red = np.tile(np.array(to_rgb(CURVE_COLOUR)), (len(ribbons), 1))

    fig = Figure(figsize=(size / 100, size / 100), dpi=100)
    ax = fig.add_axes((0, 0, 1, 0.93 if title else 1), projection="3d")
    ax.set_proj_type("ortho")
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()
    ax.computed_zorder = False
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        set_lim(c - half, c + half)
    ax.set_box_aspect((1, 1, 1), zoom=min(1.08 * fit, 50))
    both = np.concatenate([colours, red])
    ax.add_collection3d(Poly3DCollection(np.concatenate([P, ribbons]), facecolors=both,
                                         edgecolors=both, linewidths=0.3, zorder=1))
    if len(C) and width_px == thick:  # sparse curves: the hidden parts thin and faint on top
        ax.add_collection3d(Line3DCollection(segs, colors=CURVE_COLOUR, alpha=0.45,
                                             linewidths=max(0.6, thick / 3), zorder=2))
    if title:
        fig.suptitle(title, fontsize=max(7, size / 60))
    if legend:
        handles = [Patch(color=c, label=t) for t, c in legend]
        if len(C):
            handles.append(Patch(color=CURVE_COLOUR, label=f"intersection curves ({len(C)} edges)"))
        fig.legend(handles=handles, loc="lower left", fontsize=max(6, size / 90), frameon=False)
    write_atomic(png, lambda f: save_png(fig, f))
    return len(T)


def save_png(fig, f):
    """The figure as a PNG of at most 256 colours when Pillow (matplotlib's own dependency) is
    there: a third of the bytes of a full-colour PNG, the same look for flat shading."""
    import io
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100)
    try:
        from PIL import Image
        image = Image.open(buf).convert("RGB").quantize(256, dither=Image.Dither.NONE)
        image.save(f, format="PNG", optimize=True)
    except (ImportError, AttributeError):
        f.write(buf.getvalue())


# ---------------------------------------------------------------------------------------------
# One arrangement


def run_arrange(arrange, inputs, obj, timeout=None):
    """Runs arrange; its --stats JSON. ArrangeError when it fails."""
    cmd = [str(arrange), *map(str, inputs), "-o", str(obj), "--exact", "--stats"]
    try:
        p = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                           errors="replace", timeout=timeout or None)
    except subprocess.TimeoutExpired:
        raise ArrangeError(f"arrange timed out after {timeout:g} s") from None
    except OSError as e:
        raise ArrangeError(f"cannot run {arrange}: {e}") from None
    if p.returncode != 0:
        lines = [l for l in p.stderr.strip().splitlines() if l.strip()]
        why = (f"killed by {signal.Signals(-p.returncode).name}" if p.returncode < 0
               else f"exit {p.returncode}")
        raise ArrangeError(f"arrange {why}" + (f": {lines[-1].strip()}" if lines else ""))
    try:
        return json.loads(p.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        raise ArrangeError("arrange printed no --stats JSON") from None


def arrangement_curves(inputs, triangles, sources, in_triangles):
    """(curve edges, warning or None)."""
    unreadable = [str(p) for p in inputs if Path(p).suffix.lower() not in READABLE]
    if unreadable:
        return [], f"no curves: cannot read {', '.join(unreadable)} here (only OFF, OBJ, STL)"
    try:
        face_of, corners = input_faces(inputs)
    except MeshError as e:
        return [], f"no curves: {e}"
    if len(face_of) != in_triangles or (sources and max(sources) >= len(face_of)):
        return [], (f"no curves: read {len(face_of)} input triangles, arrange read "
                    f"{in_triangles}")
    return curve_edges(triangles, sources, sharing(face_of, corners)), None


def legend_of(inputs):
    return [(Path(p).name, LABEL_COLOURS[k % len(LABEL_COLOURS)]) for k, p in enumerate(inputs)]


def render(inputs, png, arrange=DEFAULT_ARRANGE, size=800, title=None, timeout=None,
           legend=True, max_faces=MAX_FACES):
    """Arranges the inputs and writes the picture to png. Returns {"in_triangles",
    "out_triangles", "drawn_triangles", "curve_edges", "warning", "seconds"}. RenderError
    (ArrangeError when arrange fails) when no picture was written."""
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="render-") as tmp:
        obj = Path(tmp) / "arrangement.obj"
        stats = run_arrange(arrange, inputs, obj, timeout)
        try:
            vertices, triangles = read_obj(obj, float_number)
            sources, labels = read_provenance(Path(f"{obj}.provenance.csv"))
        except (OSError, ValueError, KeyError, IndexError) as e:
            raise RenderError(f"cannot read arrange's output: {e!r}") from None
    if len(sources) != len(triangles) or any(len(t) != 3 for t in triangles):
        raise RenderError("arrange's output and its provenance do not match")
    curves, warning = arrangement_curves(inputs, triangles, sources, stats.get("in_triangles"))
    palette = {}
    rgb = [palette.get(l) or palette.setdefault(l, label_rgb(l)) for l in labels]
    try:
        drawn = draw(png, vertices, triangles, rgb, curves, size, title,
                     legend_of(inputs) if legend else None, max_faces)
    except (OSError, ValueError, MemoryError) as e:
        raise RenderError(f"cannot draw {png}: {e!r}") from None
    return {"in_triangles": stats.get("in_triangles"), "out_triangles": len(triangles),
            "drawn_triangles": drawn, "curve_edges": len(curves), "warning": warning,
            "seconds": round(time.monotonic() - start, 3)}


def draw_inputs(inputs, png, size=800, title=None, legend=True, max_faces=MAX_FACES):
    """The input meshes alone (polygons as fans, for the picture only), one colour per file,
    no curves. Returns the number of triangles drawn; RenderError when they cannot be read."""
    vertices, triangles, rgb = [], [], []
    for k, p in enumerate(inputs):
        try:
            vs, faces = read_mesh(p, float_number)
        except MeshError as e:
            raise RenderError(str(e)) from None
        base, colour = len(vertices), label_rgb((k,))
        vertices += vs
        for face in faces:
            for i in range(1, len(face) - 1):
                triangles.append((base + face[0], base + face[i], base + face[i + 1]))
                rgb.append(colour)
    if not triangles:
        raise RenderError("the inputs have no triangles")
    try:
        return draw(png, vertices, triangles, rgb, (), size, title,
                    legend_of(inputs) if legend else None, max_faces)
    except (OSError, ValueError, IndexError, MemoryError) as e:
        raise RenderError(f"cannot draw {png}: {e!r}") from None


# ---------------------------------------------------------------------------------------------


def main(argv=None):
    ap = Parser(prog="render.py", description=__doc__.split("\n\n")[0],
                epilog="An option that takes a value may be given once; exit status 2 for a bad "
                       "command line.")
    ap.add_argument("inputs", nargs="+", type=path, metavar="INPUT",
                    help="mesh files, one label each")
    ap.add_argument("-o", "--output", required=True, type=path, help="the picture (.png)")
    ap.add_argument("--arrange", type=path, default=DEFAULT_ARRANGE,
                    help="the arrange tool (default: %(default)s)")
    ap.add_argument("--size", type=integer(64, 8192), default=800,
                    help="width and height in pixels, 64 to 8192 (default: 800)")
    ap.add_argument("--title", type=text, help="a title over the picture (default: none)")
    ap.add_argument("--timeout", type=seconds(0, 10**7), default=0,
                    help="seconds arrange may take, 0 for none (default: 0)")
    args = ap.parse_args(argv)
    missing = [str(p) for p in args.inputs if not p.is_file()]
    if missing:
        ap.error(f"no such input file: {', '.join(missing)}")
    if not os.access(args.arrange, os.X_OK) or args.arrange.is_dir():
        ap.error(f"--arrange {args.arrange}: no such executable (build it: cmake --build build "
                 "--target arrange)")
    if args.output.suffix.lower() != ".png":
        ap.error(f"-o/--output {args.output}: the picture's name must end in .png")
    if not args.output.parent.is_dir():
        ap.error(f"-o/--output {args.output}: no such folder {args.output.parent}")
    try:
        summary = render(args.inputs, args.output, args.arrange, args.size, args.title,
                         args.timeout)
    except RenderError as e:
        print(f"render.py: {e}", file=sys.stderr)
        return 1
    if summary["warning"]:
        print(f"render.py: warning: {summary['warning']}", file=sys.stderr)
    print(f"render.py: wrote {args.output}: {summary['out_triangles']} triangles "
          f"({summary['drawn_triangles']} drawn), {summary['curve_edges']} curve edges, "
          f"{summary['seconds']:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
