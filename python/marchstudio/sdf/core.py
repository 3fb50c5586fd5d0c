"""The shape object: one node of marchstudio's scene graph (docs/scene-graph.md)
held with its children and its placement, in fogleman/sdf's words.

A shape is immutable: every method returns a new one. Its placement is kept
as one similarity (uniform scale, rotation, translation) and written as the
node's `translate`/`rotate`/`scale`, or as `matrix` once two turns compose.
"""
import json
import math

import numpy as np

ORIGIN = np.array((0.0, 0.0, 0.0))
X = np.array((1.0, 0.0, 0.0))
Y = np.array((0.0, 1.0, 0.0))
Z = np.array((0.0, 0.0, 1.0))
UP = Z
pi = math.pi


def refuse(name, instead):
    """Raises for a fogleman/sdf function the graph cannot express."""
    raise NotImplementedError(f"marchstudio.sdf: {name}() has no scene-graph node: {instead}")


def vec(v, n=3, name='value'):
    """A number or a sequence as n floats."""
    a = np.asarray(v, dtype=float).reshape(-1)
    if a.size == 1:
        a = np.repeat(a, n)
    if a.size != n or not np.all(np.isfinite(a)):
        raise ValueError(f"marchstudio.sdf: {name} must be a finite number or {n} numbers, not {v!r}")
    return a


def half_size(size, center, a, b, n):
    """fogleman's box and rectangle: (half size, center) from size and
    center, or from the corners a and b when both are given."""
    if a is not None and b is not None:
        a, b = vec(a, n, 'a'), vec(b, n, 'b')
        size, center = b - a, (a + b) / 2
    return vec(size, n, 'size') / 2, center


def num(v, name='value'):
    if isinstance(v, (list, tuple, np.ndarray)) or not math.isfinite(float(v)):
        raise ValueError(f"marchstudio.sdf: {name} must be a finite number, not {v!r}")
    return float(v)


def rotation(axis, degrees):
    """Right-handed turn by `degrees` round `axis` (Rodrigues), as the graph's `rotate`."""
    k = np.asarray(axis, dtype=float)
    k = k / np.linalg.norm(k)
    a = math.radians(degrees)
    kx = np.array(((0, -k[2], k[1]), (k[2], 0, -k[0]), (-k[1], k[0], 0)))
    return np.eye(3) * math.cos(a) + math.sin(a) * kx + (1 - math.cos(a)) * np.outer(k, k)


def turn_onto(src, dst):
    """(axis, degrees) turning unit `src` onto the direction of `dst`."""
    d = np.asarray(dst, dtype=float)
    d = d / np.linalg.norm(d)
    axis = np.cross(src, d)
    angle = math.degrees(math.acos(max(-1.0, min(1.0, float(np.dot(src, d))))))
    if np.linalg.norm(axis) < 1e-9:
        axis = np.array((1.0, 0.0, 0.0)) if abs(src[0]) < 0.9 else np.array((0.0, 1.0, 0.0))
        axis = np.cross(src, axis)
    return axis / np.linalg.norm(axis), angle


def plain(v):
    """JSON-ready numbers: floats, integers kept, tidy zeros."""
    if isinstance(v, np.ndarray):
        v = v.tolist()
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    if isinstance(v, float):
        r = round(v, 9)
        return 0.0 if r == 0 else r
    return v


class SDF:
    """A shape: a graph node (`sdf` primitive or `op` with children)."""

    dim = 3

    def __init__(self, node, children=()):
        self.node = dict(node)
        self.children = list(children)
        self._k = None
        self._s = 1.0
        self._t = np.zeros(self.dim)
        self._turn = np.eye(3) if self.dim == 3 else 0.0
        self._axis_deg = None  # the one turn, while the node has had one

    def _copy(self):
        c = object.__new__(type(self))
        c.__dict__.update(self.__dict__)
        c.node = dict(self.node)
        c.children = list(self.children)
        return c

    def _wrap(self, op, **params):
        """A one-child modifier round this shape."""
        return type(self)(dict(op=op, **params), [self])

    # fogleman's operators ---------------------------------------------------
    def __or__(self, other):
        return union(self, other)

    def __and__(self, other):
        return intersection(self, other)

    def __sub__(self, other):
        return difference(self, other)

    def k(self, k=None):
        c = self._copy()
        c._k = k
        return c

    def union(self, *bs, k=None):
        return union(self, *bs, k=k)

    def difference(self, *bs, k=None):
        return difference(self, *bs, k=k)

    def intersection(self, *bs, k=None):
        return intersection(self, *bs, k=k)

    def blend(self, *bs, k=0.5):
        return blend(self, *bs, k=k)

    def dilate(self, r):
        return self._wrap('dilate', r=num(r, 'r'))

    def erode(self, r):
        return self._wrap('erode', r=num(r, 'r'))

    def shell(self, thickness):
        return self._wrap('shell', thickness=num(thickness, 'thickness'))

    def elongate(self, size):
        return self._wrap('elongate', h=vec(size, self.dim, 'size'))

    def translate(self, offset):
        c = self._copy()
        c._t = self._t + vec(offset, self.dim, 'offset')[:self.dim]
        return c

    # the graph's written form -----------------------------------------------
    def to_node(self):
        """The node as a dict, children and placement included."""
        out = {k: plain(v) for k, v in self.node.items()}
        out.update(self._placement())
        if self.children:
            out['children'] = [c.to_node() for c in self.children]
        return out

    def to_json(self, path=None, indent=1):
        """The graph file `{"root": NODE}`: its text, written to `path` when given."""
        text = json.dumps({'root': self.to_node()}, indent=indent) + '\n'
        if path is not None:
            from .._files import write_text_atomic
            write_text_atomic(path, text)
        return text

    def save(self, path, step=None, bounds=None, samples=2**22, workers=None, batch_size=None,
             verbose=False, sparse=True):
        """Meshes the shape to `path` (.stl .obj .ply .glb .vdb), atomically."""
        from .._mesh import save
        return save(self, path, step=step, bounds=bounds, samples=samples)

    def generate(self, step=None, bounds=None, samples=2**22, workers=None, batch_size=None,
                 verbose=False, sparse=True):
        """The triangles' corners, 3 per triangle: an (3T, 3) float32 array."""
        from .._mesh import generate
        return generate(self, step=step, bounds=bounds, samples=samples)

    def show_slice(self, *args, **kwargs):
        refuse('show_slice', 'render the shape with marchstudio.Scene(shape).render() instead')

    def bend_linear(self, *args, **kwargs):
        refuse('bend_linear', 'there is no shear modifier; bend() or twist() may do')

    def bend_radial(self, *args, **kwargs):
        refuse('bend_radial', 'there is no radial shear modifier')

    def transition_linear(self, *args, **kwargs):
        refuse('transition_linear', 'blend(other, k) mixes two shapes by one weight')

    def transition_radial(self, *args, **kwargs):
        refuse('transition_radial', 'blend(other, k) mixes two shapes by one weight')

    def _repr_png_(self):
        """Jupyter's picture of a 3D shape: Scene(shape)._repr_png_()."""
        if self.dim != 3:
            return None  # a 2D shape has no picture until extruded or revolved
        from .._scene import Scene
        return Scene(self)._repr_png_()

    def __repr__(self):
        return f"<marchstudio.sdf {type(self).__name__} {self.node.get('sdf') or self.node.get('op')}>"


def _fold(kind, smooth, a, bs, k):
    """fogleman's union/difference/intersection: folded left, each b's own k."""
    if not bs:
        raise ValueError(f"marchstudio.sdf: {kind} needs two shapes or more")
    node = a
    for b in bs:
        if not isinstance(b, SDF) or b.dim != a.dim:
            raise ValueError(f"marchstudio.sdf: {kind} of a {a.dim}D shape and {b!r}")
        kk = k if k is not None else b._k
        op = dict(op=smooth, k=num(kk, 'k')) if kk else dict(op=kind)
        if node.node == op and not node._is_placed() and node._k is None:
            node = node._copy()
            node.children.append(b)
        else:
            node = type(a)(op, [node, b])
    return node


def union(a, *bs, k=None):
    return _fold('opUnion', 'opSmoothUnion', a, bs, k)


def difference(a, *bs, k=None):
    return _fold('opSubtraction', 'opSmoothSubtraction', a, bs, k)


def intersection(a, *bs, k=None):
    return _fold('opIntersection', 'opSmoothIntersection', a, bs, k)


def blend(a, *bs, k=0.5):
    node = a
    for b in bs:
        node = type(a)(dict(op='opBlend', t=num(k, 'k')), [node, b])
    return node
