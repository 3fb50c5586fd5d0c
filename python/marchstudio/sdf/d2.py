"""fogleman/sdf's 2D shapes as the graph's profiles (`sd2*`): each lives
under extrude() or revolve(), where the graph takes its 2D transforms
(`translate` [x, y], `rotate` in degrees, `scale`)."""
import math

import numpy as np

from .core import SDF, ORIGIN, X, half_size, num, plain, refuse, vec
from .d3 import SDF3


class SDF2(SDF):
    dim = 2

    def _is_placed(self):
        return self._s != 1.0 or bool(np.any(self._t)) or self._turn != 0.0

    def _placement(self):
        out = {}
        if self._turn:
            out['rotate'] = plain(float(self._turn))
        if self._s != 1.0:
            out['scale'] = plain(float(self._s))
        if np.any(self._t):
            out['translate'] = plain([float(x) for x in self._t])
        return out

    def translate(self, offset):
        c = self._copy()
        c._t = self._t + vec(offset, 3 if np.size(offset) == 3 else 2, 'offset')[:2]
        return c

    def scale(self, factor):
        f = vec(factor, 2, 'factor')
        if np.any(f <= 0) or not np.allclose(f, f[0]):
            raise ValueError(f"marchstudio.sdf: a 2D scale must be one factor > 0, not {factor!r}")
        c = self._copy()
        c._s = self._s * float(f[0])
        c._t = self._t * float(f[0])
        return c

    def rotate(self, angle):
        deg = math.degrees(num(angle, 'angle'))
        c = self._copy()
        a = math.radians(deg)
        r = np.array(((math.cos(a), -math.sin(a)), (math.sin(a), math.cos(a))))
        c._turn = self._turn + deg
        c._t = r @ self._t
        return c

    def extrude(self, h):
        return SDF3(dict(op='extrude', h=num(h, 'h')), [self])

    def revolve(self, offset=0):
        # ours sweeps round y, fogleman's round z
        return SDF3(dict(op='revolve', offset=num(offset, 'offset')), [self])._turned(X, 90.0)

    def extrude_to(self, *args, **kwargs):
        refuse('extrude_to', 'extrude() one profile; blend() two extrusions for a mix')


def _at(node, center=ORIGIN):
    s = SDF2(node)
    c = vec(center, 3 if np.size(center) == 3 else 2, 'center')[:2]
    return s.translate(c) if np.any(c) else s


def circle(radius=1, center=ORIGIN):
    return _at(dict(sdf='sd2Circle', r=num(radius, 'radius')), center)


def rectangle(size=1, center=ORIGIN, a=None, b=None):
    half, center = half_size(size, center, a, b, 2)
    return _at(dict(sdf='sd2Box', b=half), center)


def rounded_rectangle(size, radius, center=ORIGIN):
    if np.size(radius) != 1:
        refuse('rounded_rectangle (a radius per corner)', 'give one radius')
    return _at(dict(sdf='sd2RoundBox', b=vec(size, 2, 'size') / 2, r=num(radius, 'radius')), center)


def equilateral_triangle():
    return SDF2(dict(sdf='sd2EquilateralTriangle', r=2 / math.sqrt(3)))


def hexagon(r):
    return SDF2(dict(sdf='sd2Hexagon', r=num(r, 'r')))


def rounded_x(w, r):
    h = num(w, 'w') / 2
    cross = SDF2(dict(op='opUnion'), [SDF2(dict(sdf='ud2Segment', a=[-h, -h], b=[h, h])),
                                       SDF2(dict(sdf='ud2Segment', a=[-h, h], b=[h, -h]))])
    return SDF2(dict(op='round', r=num(r, 'r')), [cross])


def polygon(points):
    p = np.asarray(points, dtype=float)
    if p.ndim != 2 or p.shape[1] != 2:
        raise ValueError('polygon: points must be (x, y) pairs, not an array of shape %s' % (p.shape,))
    # The graph takes each vertex once: a point repeating the one before it
    # (or the first, closing the loop) adds nothing to the shape.
    keep = [q for i, q in enumerate(p) if i == 0 or not np.array_equal(q, p[i - 1])]
    if len(keep) > 1 and np.array_equal(keep[-1], keep[0]):
        keep.pop()
    if len(keep) < 3:
        raise ValueError('polygon: needs 3 or more distinct points, not %d' % len(keep))
    if len(keep) == 3:
        return SDF2(dict(sdf='sd2Triangle', a=keep[0], b=keep[1], c=keep[2]))
    if len(keep) > 32:
        refuse('polygon (more than 32 points)', 'union polygons of up to 32 points each')
    return SDF2(dict(sdf='sd2Polygon', v=[[float(x), float(y)] for x, y in keep]))


def line(normal=None, point=ORIGIN):
    refuse('line', 'there is no 2D half-plane; cut the extruded solid with plane() instead')


def sdf2(*args, **kwargs):
    refuse('sdf2', 'a Python function is not a graph node; build the profile from the functions here')


def extrude(other, h):
    return other.extrude(h)


def extrude_to(a, b, h, e=None):
    return a.extrude_to(b, h, e)


def revolve(other, offset=0):
    return other.revolve(offset)
