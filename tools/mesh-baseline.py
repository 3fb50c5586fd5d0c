#!/usr/bin/python3
"""The dense baseline for `marchstudio mesh` (docs/mesh.md): map() at every
voxel of the grid with numpy, then skimage's marching cubes.

  /usr/bin/python3 tools/mesh-baseline.py --subject seed|part|molecule --resolution N

Prints one JSON line: subject, resolution, sample_s, mc_s, seconds,
triangles, peak_rss_mb. The fields are ports of sdf_shaders/ (the
functions the subjects use, nothing else) and of scene/graph_build.cpp's
transforms, left fold and boxes, so both sides mesh the same surface over
the same grid: voxel = longest side of the scene's bounds / N, 2 voxels of
padding on every side. For seed it also checks every vertex against the
analytic sphere (stderr); --check-voxels sets the tolerance.
"""
import argparse
import json
import math
import resource
import sys
import time
from pathlib import Path

import numpy as np
from skimage import measure

ROOT = Path(__file__).resolve().parent.parent
F = np.float32

# ---- sdf_shaders/ ports: p is (x, y, z), float32 arrays, in the leaf's space ----


def length(x, y, z):
    return np.sqrt(x * x + y * y + z * z)


def box_q2(qx, qy):  # common.glsl msBoxQ(vec2)
    return np.hypot(np.maximum(qx, 0), np.maximum(qy, 0)) + np.minimum(np.maximum(qx, qy), 0)


def box_q3(qx, qy, qz):  # common.glsl msBoxQ(vec3)
    outside = length(np.maximum(qx, 0), np.maximum(qy, 0), np.maximum(qz, 0))
    return outside + np.minimum(np.maximum(np.maximum(qx, qy), qz), 0)


def sd_sphere(p, r):
    return length(*p) - r


def sd_box(p, b):
    return box_q3(*(np.abs(c) - bc for c, bc in zip(p, b)))


def sd_round_box(p, b, r):
    return box_q3(*(np.abs(c) - bc + r for c, bc in zip(p, b))) - r


def sd_cylinder(p, r, h):
    return box_q2(np.hypot(p[0], p[2]) - r, np.abs(p[1]) - h)


def sd2_hexagon(x, y, r):  # primitives2d.glsl
    nx, ny = F(0.8660254), F(-0.5)
    x, y = np.abs(x), np.abs(y)
    d = 2 * np.maximum(x * nx + y * ny, 0)
    x, y = x - d * nx, y - d * ny
    qx = x - np.clip(x, F(-0.57735027) * r, F(0.57735027) * r)
    qy = y - r
    ln = np.hypot(qx, qy)
    return np.where(qy < 0, -ln, ln)


def sd_hex_prism(p, h):  # primitives_poly.glsl
    return box_q2(sd2_hexagon(p[0], p[1], h[0]), np.abs(p[2]) - h[1])


# name: (function, parameter names in the order graph_vocab.cpp reads them)
PRIMS = {
    "sdSphere": (lambda p, a: sd_sphere(p, a["r"]), ["r"]),
    "sdBox": (lambda p, a: sd_box(p, a["b"]), ["b"]),
    "sdRoundBox": (lambda p, a: sd_round_box(p, a["b"], a["r"]), ["b", "r"]),
    "sdCylinder": (lambda p, a: sd_cylinder(p, a["r"], a["h"]), ["r", "h"]),
    "sdHexPrism": (lambda p, a: sd_hex_prism(p, a["h"]), ["h"]),
}


def op_smooth_union(a, b, k):  # operators.glsl, the quadratic smin
    h = np.maximum(k - np.abs(a - b), 0) / max(k, 1e-6)
    return np.minimum(a, b) - h * h * (k * F(0.25))


def op_intersection_chamfer(a, b, r):  # combinators.glsl
    return np.maximum(np.maximum(a, b), (a + b + r) * F(0.70710678))


OPS = {
    "opUnion": (lambda a, b, k: np.minimum(a, b), []),
    "opIntersection": (lambda a, b, k: np.maximum(a, b), []),
    "opSubtraction": (lambda a, b, k: np.maximum(a, -b), []),
    "opSmoothUnion": (lambda a, b, k: op_smooth_union(a, b, k["k"]), ["k"]),
    "opUnionChamfer": (lambda a, b, k: np.minimum(np.minimum(a, b), (a + b - k["r"]) * F(0.70710678)), ["r"]),
    "opSubtractionChamfer": (lambda a, b, k: op_intersection_chamfer(a, -b, k["r"]), ["r"]),
}

# ---- scene/graph_build.cpp and graph_vocab.cpp: transforms and boxes ----

INF = math.inf


def axis_angle(axis, degrees):
    a = math.radians(degrees)
    u = np.asarray(axis, float) / np.linalg.norm(axis)
    c, s = math.cos(a), math.sin(a)
    k = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    return c * np.eye(3) + (1 - c) * np.outer(u, u) + s * k  # Rodrigues, row-major


def transform(node, parent):
    """World to local, q = A p + b, distances times s, as Builder::transform."""
    rot, t, s = np.eye(3), np.zeros(3), float(node.get("scale", 1.0))
    if "matrix" in node:
        sys.exit("mesh-baseline: 'matrix' transforms are not ported")
    if "rotate" in node:
        r = node["rotate"]
        rot = axis_angle(r[:3], r[3])
    if "translate" in node:
        t = np.asarray(node["translate"], float)
    inv = rot.T / s
    A, b, ps = parent
    return inv @ A, inv @ (b - t), ps * s


def prim_box(name, a):
    sym = lambda x, y, z: (np.array([-x, -y, -z]), np.array([x, y, z]))
    if name == "sdSphere":
        return sym(a["r"], a["r"], a["r"])
    if name in ("sdBox", "sdRoundBox"):
        return sym(*a["b"])
    if name == "sdCylinder":
        return sym(a["r"], a["h"], a["r"])
    if name == "sdHexPrism":
        return sym(a["h"][0] * 1.1547006, a["h"][0], a["h"][1])
    raise KeyError(name)


def world_box(local, xf):
    A, b, s = xf
    inv = A.T * (s * s)
    o = -(inv @ b)
    lo, hi = o.copy(), o.copy()
    for i in range(3):
        for j in range(3):
            m = inv[i, j]
            if abs(m) < 1e-7:
                continue
            x, y = m * local[0][j], m * local[1][j]
            lo[i] += min(x, y)
            hi[i] += max(x, y)
    g = 1e-5 * (1 + np.linalg.norm(np.maximum(np.abs(lo), np.abs(hi))))
    return lo - g, hi + g


class Node:
    """A leaf (fn, args, xf) or a folded binary operator, with core and slack."""

    def __init__(self, **kw):
        self.__dict__.update(kw)

    def box(self, extra=0.0):
        return self.core[0] - self.slack - extra, self.core[1] + self.slack + extra


def combine(op, a, b, args):
    uni = lambda slack: ((np.minimum(a.core[0], b.core[0]), np.maximum(a.core[1], b.core[1])), slack)
    if op == "opUnion":
        core, slack = uni(max(a.slack, b.slack))
    elif op == "opSmoothUnion":
        k = args["k"]
        worst = max(a.slack, b.slack) + 0.25 * k
        slack = worst if min(a.slack, b.slack) > 0 else min(worst, max(a.slack, b.slack, k))
        core, slack = uni(slack)
    elif op == "opUnionChamfer":
        core, slack = uni(max(a.slack, b.slack) + args["r"])
    elif op == "opIntersection":
        (la, ha), (lb, hb) = a.box(), b.box()
        core, slack = (np.maximum(la, lb), np.minimum(ha, hb)), 0.0
    else:  # the subtractions: inside a
        core, slack = a.box(), 0.0
    return Node(leaf=False, op=op, left=a, right=b, args=args, core=core, slack=slack)


def read_args(node, names, scale=1.0):
    return {n: F(np.asarray(node[n], float) * scale) for n in names}


def build(node, parent=(np.eye(3), np.zeros(3), 1.0)):
    """The graph as Builder does it: n-ary operators folded left."""
    xf = transform(node, parent)
    if "sdf" in node:
        fn, names = PRIMS[node["sdf"]]
        args = read_args(node, names)
        box = world_box(prim_box(node["sdf"], args), xf)
        return Node(leaf=True, fn=fn, args=args, xf=xf, core=box, slack=0.0)
    args = read_args(node, OPS[node["op"]][1], xf[2])  # lengths in world units
    kids = [build(c, xf) for c in node["children"]]
    acc = kids[0]
    for c in kids[1:]:
        acc = combine(node["op"], acc, c, args)
    return acc


def to_local(p, A, b):
    """A p + b; a translation (the molecule's 1,000 leaves) skips the product."""
    if np.array_equal(A, np.eye(3)):
        return tuple(c + F(bc) for c, bc in zip(p, b))
    return tuple(F(A[i, 0]) * p[0] + F(A[i, 1]) * p[1] + F(A[i, 2]) * p[2] + F(b[i]) for i in range(3))


def evaluate(n, p):
    """Postfix without recursion: a left fold of 1,000 is 1,000 deep."""
    stack, out = [(n, False)], []
    while stack:
        m, ready = stack.pop()
        if m.leaf:
            d = m.fn(to_local(p, *m.xf[:2]), m.args)
            s = m.xf[2]
            out.append(d * F(s) if s != 1.0 else d)
        elif ready:
            right, left = out.pop(), out.pop()
            out.append(OPS[m.op][0](left, right, m.args))
        else:
            stack += [(m, True), (m.right, False), (m.left, False)]
    return out[0]


# ---- subjects ----


def seed_subject():
    c, r = np.array([0.0, 1.0, 0.0]), 1.02  # seed.toml [bounds]
    field = lambda p: sd_sphere(to_local(p, np.eye(3), -c), F(1.0))
    return field, c - r, c + r


def graph_subject(json_name):
    root = build(json.loads((ROOT / "scenes" / json_name).read_text())["root"])
    lo, hi = root.box()
    pad = 1e-3 * np.linalg.norm(hi - lo) + 1e-3  # graph_scene.cpp bounds_of
    return (lambda p: evaluate(root, p)), lo - pad, hi + pad


SUBJECTS = {"seed": seed_subject, "part": lambda: graph_subject("part.json"),
            "molecule": lambda: graph_subject("molecule.json")}


def sample(field, lo, hi, n, chunk_points):
    """Every grid point, a slab of z at a time (bounds the temporaries)."""
    h = float(np.max(hi - lo)) / n
    cells = np.ceil((hi - lo) / h - 1e-6).astype(int) + 4
    origin = lo - 2 * h
    nx, ny, nz = cells + 1
    vol = np.empty((nz, ny, nx), F)
    xs = (origin[0] + h * np.arange(nx)).astype(F)
    ys = (origin[1] + h * np.arange(ny)).astype(F)
    slab = max(1, chunk_points // (nx * ny))
    for z0 in range(0, nz, slab):
        zs = (origin[2] + h * np.arange(z0, min(nz, z0 + slab))).astype(F)
        Z, Y, X = np.meshgrid(zs, ys, xs, indexing="ij")
        p = (X.ravel(), Y.ravel(), Z.ravel())
        vol[z0:z0 + len(zs)] = field(p).reshape(len(zs), ny, nx)
    return vol, origin, h


def check_seed(verts, h, tol):
    r = np.linalg.norm(verts - np.array([0.0, 1.0, 0.0]), axis=1)
    err = np.abs(r - 1.0) / h
    ok = err.max() <= tol
    print(f"seed check: {len(verts)} vertices, |r - 1| max {err.max():.4f} voxel, mean {err.mean():.4f}"
          f" (tolerance {tol}): {'ok' if ok else 'FAILED'}", file=sys.stderr)
    return ok


def write_ply(path, verts, faces):
    """Binary PLY in the layout `marchstudio mesh` writes, less its normals, material 0 throughout."""
    v = np.zeros(len(verts), dtype=[("p", "<f4", 3), ("m", "<u2")])
    v["p"] = verts
    f = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<u4", 3)])
    f["n"], f["i"] = 3, faces
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(v)}\n"
            "property float x\nproperty float y\nproperty float z\nproperty ushort material\n"
            f"element face {len(f)}\nproperty list uchar uint vertex_indices\nend_header\n")
    with open(path, "wb") as out:
        out.write(head.encode())
        out.write(v.tobytes())
        out.write(f.tobytes())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--subject", choices=sorted(SUBJECTS), required=True)
    ap.add_argument("--resolution", type=int, default=128, help="cells along the bounds' longest side")
    ap.add_argument("--chunk-points", type=int, default=1 << 21, help="points per slab of z")
    ap.add_argument("--check-voxels", type=float, default=0.5)
    ap.add_argument("--ply", type=Path, help="also write the mesh (the exporter's binary PLY layout)")
    a = ap.parse_args()
    t0 = time.perf_counter()
    field, lo, hi = SUBJECTS[a.subject]()
    vol, origin, h = sample(field, np.asarray(lo, float), np.asarray(hi, float), a.resolution, a.chunk_points)
    t1 = time.perf_counter()
    verts, faces, _, _ = measure.marching_cubes(vol, level=0.0, spacing=(h, h, h), allow_degenerate=False,
                                              gradient_direction="ascent")  # SDF: negative inside
    t2 = time.perf_counter()
    verts = verts[:, ::-1] + origin  # (z, y, x) to (x, y, z)
    if a.ply:
        write_ply(a.ply, verts, faces)
    ok = check_seed(verts, h, a.check_voxels) if a.subject == "seed" else True
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print(json.dumps({"subject": a.subject, "resolution": a.resolution, "sample_s": round(t1 - t0, 3),
                      "mc_s": round(t2 - t1, 3), "seconds": round(time.perf_counter() - t0, 3),
                      "triangles": int(len(faces)), "peak_rss_mb": round(peak, 1)}))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
