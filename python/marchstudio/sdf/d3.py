"""fogleman/sdf's 3D shapes and operations as graph nodes. Each conversion is
a row of docs/scene-graph.md's coverage table (tools/coverage_rows.py):
the graph is in fogleman's Z-up coordinates, so points carry over, and the
primitives built round y are turned onto z here."""
import math

import numpy as np

from .core import SDF, ORIGIN, UP, X, Y, Z, half_size, num, plain, refuse, rotation, turn_onto, vec


class SDF3(SDF):
    dim = 3

    def _is_placed(self):
        return self._s != 1.0 or bool(np.any(self._t)) or not np.allclose(self._turn, np.eye(3))

    def _placement(self):
        out = {}
        if not np.allclose(self._turn, np.eye(3), atol=1e-12):
            if self._axis_deg is None:
                m = np.hstack((self._s * self._turn, self._t.reshape(3, 1)))
                return {'matrix': plain([float(x) for x in m.reshape(-1)])}
            axis, deg = self._axis_deg
            out['rotate'] = plain([float(axis[0]), float(axis[1]), float(axis[2]), float(deg)])
        if self._s != 1.0:
            out['scale'] = plain(float(self._s))
        if np.any(self._t):
            out['translate'] = plain([float(x) for x in self._t])
        return out

    def _turned(self, axis, degrees):
        c = self._copy()
        r = rotation(axis, degrees)
        c._axis_deg = (np.asarray(axis, float), degrees) if np.allclose(self._turn, np.eye(3)) else None
        c._turn = r @ self._turn
        c._t = r @ self._t
        return c

    def scale(self, factor):
        f = vec(factor, 3, 'factor')
        if np.any(f <= 0):
            raise ValueError(f"marchstudio.sdf: scale factors must be > 0, not {factor!r}")
        if np.allclose(f, f[0]):
            c = self._copy()
            c._s = self._s * float(f[0])
            c._t = self._t * float(f[0])
            return c
        return self._wrap('scale', s=f)

    def rotate(self, angle, vector=Z):
        return self._turned(vec(vector, 3, 'vector'), math.degrees(num(angle, 'angle')))

    def orient(self, axis):
        a = vec(axis, 3, 'axis')
        a = a / np.linalg.norm(a)
        cross = np.cross(a, Z)
        angle = math.degrees(math.acos(max(-1.0, min(1.0, float(np.dot(a, Z))))))
        if np.linalg.norm(cross) < 1e-9:
            return self if angle < 90 else self._turned(Y, 180.0)  # fogleman turns round Y then
        return self._turned(cross, angle)

    def repeat(self, spacing, count=None, padding=0):
        params = dict(spacing=vec(spacing, 3, 'spacing'))
        if count is not None:
            params['count'] = [int(c) for c in vec(count, 3, 'count')]
        return self._wrap('repeat', **params)

    def circular_array(self, count, offset=0):
        return self._wrap('polar', count=int(count), radius=num(offset, 'offset'), axis=[0, 0, 1])

    def twist(self, k):
        return self._wrap('twist', k=-num(k, 'k'), axis=[0, 0, 1])

    def bend(self, k):
        return self._wrap('bend', k=num(k, 'k'))

    def slice(self):
        refuse('slice', 'a profile cannot hold a 3D subtree; build the profile from 2D shapes')


def _at(node, center=ORIGIN):
    s = SDF3(node)
    c = vec(center, 3, 'center')
    return s.translate(c) if np.any(c) else s


def _upright(node):
    """A primitive built round y, turned onto fogleman's z."""
    return SDF3(node)._turned(X, 90.0)


def sphere(radius=1, center=ORIGIN):
    return _at(dict(sdf='sdSphere', r=num(radius, 'radius')), center)


def box(size=1, center=ORIGIN, a=None, b=None):
    half, center = half_size(size, center, a, b, 3)
    return _at(dict(sdf='sdBox', b=half), center)


def rounded_box(size, radius):
    return SDF3(dict(sdf='sdRoundBox', b=vec(size, 3, 'size') / 2, r=num(radius, 'radius')))


def wireframe_box(size, thickness):
    t = num(thickness, 'thickness')
    return SDF3(dict(sdf='sdBoxFrame', b=(vec(size, 3, 'size') + t) / 2, e=t / 2))


def torus(r1, r2):
    return _upright(dict(sdf='sdTorus', t=[num(r1, 'r1'), num(r2, 'r2')]))


def capsule(a, b, radius):
    return SDF3(dict(sdf='sdCapsule', a=vec(a, 3, 'a'), b=vec(b, 3, 'b'), r=num(radius, 'radius')))


def capped_cylinder(a, b, radius):
    return SDF3(dict(sdf='sdCappedCylinder', a=vec(a, 3, 'a'), b=vec(b, 3, 'b'), r=num(radius, 'radius')))


def rounded_cylinder(ra, rb, h):
    return _upright(dict(sdf='sdRoundedCylinder', r=num(ra, 'ra'), e=num(rb, 'rb'), h=num(h, 'h') / 2))


def capped_cone(a, b, ra, rb):
    a, b = vec(a, 3, 'a'), vec(b, 3, 'b')
    axis, deg = turn_onto(Y, b - a)
    s = SDF3(dict(sdf='sdCappedCone', h=float(np.linalg.norm(b - a)) / 2, r1=num(ra, 'ra'), r2=num(rb, 'rb')))
    return s._turned(axis, deg).translate((a + b) / 2)


def rounded_cone(r1, r2, h):
    return _upright(dict(sdf='sdRoundCone', r1=num(r1, 'r1'), r2=num(r2, 'r2'), h=num(h, 'h')))


def ellipsoid(size):
    return SDF3(dict(sdf='sdEllipsoid', r=vec(size, 3, 'size')))


def pyramid(h):
    return _upright(dict(sdf='sdPyramid', h=num(h, 'h')))


def tetrahedron(r=1):
    # fogleman's ignores r: four face planes, with a cube round them to bound them.
    i = 0.57735
    planes = [SDF3(dict(sdf='sdPlane', n=[x * i, y * i, z * i], w=-i))
              for x, y, z in ((1, 1, -1), (-1, -1, -1), (1, -1, 1), (-1, 1, 1))]
    return SDF3(dict(op='opIntersection'), [SDF3(dict(sdf='sdBox', b=[1, 1, 1]))] + planes)


def octahedron(r=1):
    return SDF3(dict(sdf='sdOctahedron', s=num(r, 'r')))


def dodecahedron(r=1):
    return SDF3(dict(sdf='sdDodecahedron', r=0.850651 * num(r, 'r')))._turned(Z, 90.0)


def icosahedron(r=1):
    return SDF3(dict(sdf='sdIcosahedron', r=0.934172 * num(r, 'r')))._turned(Z, 90.0)


def plane(normal=UP, point=ORIGIN):
    n = vec(normal, 3, 'normal')
    n = n / np.linalg.norm(n)
    return SDF3(dict(sdf='sdPlane', n=-n, w=float(np.dot(vec(point, 3, 'point'), n))))


def slab(x0=None, y0=None, z0=None, x1=None, y1=None, z1=None, k=None):
    if k is not None:
        refuse('slab(k=...)', 'blended corners have no counterpart; round the result with dilate()')
    node = dict(sdf='sdSlab')
    for axis, lo, hi in (('x', x0, x1), ('y', y0, y1), ('z', z0, z1)):
        if lo is not None or hi is not None:
            node[axis] = [None if lo is None else num(lo), None if hi is None else num(hi)]
    return SDF3(node)


def cylinder(radius):
    return _upright(dict(sdf='sdInfiniteCylinder', c=[0.0, 0.0, num(radius, 'radius')]))


def sdf3(*args, **kwargs):
    refuse('sdf3', 'a Python function is not a graph node; build the shape from the functions here')


def image(*args, **kwargs):
    refuse('image', 'there is no image node; trace the outline as 2D shapes and extrude()')


def text(*args, **kwargs):
    refuse('text', 'there is no text node; build the letters from 2D shapes')


def bend_linear(other, *args, **kwargs):
    return other.bend_linear(*args, **kwargs)


def bend_radial(other, *args, **kwargs):
    return other.bend_radial(*args, **kwargs)


def transition_linear(*args, **kwargs):
    refuse('transition_linear', 'blend(a, b, k=...) mixes two shapes by one weight')


def transition_radial(*args, **kwargs):
    refuse('transition_radial', 'blend(a, b, k=...) mixes two shapes by one weight')


def slice(other):  # noqa: A001 (fogleman's name)
    return other.slice()
