"""The conventions carry over exactly: fogleman/sdf's own formulas (written
out here in numpy, as its sdf/d3.py has them), evaluated at the vertices
of our mesh of the same shape, are zero to within a cell."""
import numpy as np
import pytest

from marchstudio.sdf import X, Y, Z, box, capped_cone, cylinder, pi, plane, sphere, torus
import marchstudio


def length(a):
    return np.linalg.norm(a, axis=1)


def f_sphere(p, r=1.0):
    return length(p) - r


def f_box(p, size):
    q = np.abs(p) - np.asarray(size) / 2
    return length(np.maximum(q, 0)) + np.minimum(q.max(axis=1), 0)


def f_cylinder(p, r):
    return length(p[:, :2]) - r


def f_torus(p, r1, r2):
    a = length(p[:, :2]) - r1
    return length(np.stack((a, p[:, 2]), axis=1)) - r2


def f_rotate(p, angle, v):
    """fogleman's rotate(other, angle, vector): the point turned by -angle."""
    x, y, z = np.asarray(v, float) / np.linalg.norm(v)
    s, c = np.sin(angle), np.cos(angle)
    m = 1 - c
    mat = np.array([[m*x*x + c, m*x*y + z*s, m*z*x - y*s],
                    [m*x*y - z*s, m*y*y + c, m*y*z + x*s],
                    [m*z*x + y*s, m*y*z - x*s, m*z*z + c]]).T
    return p @ mat


def f_twist(p, k):
    c, s = np.cos(k * p[:, 2]), np.sin(k * p[:, 2])
    return np.stack((c * p[:, 0] - s * p[:, 1], s * p[:, 0] + c * p[:, 1], p[:, 2]), axis=1)


def f_bend(p, k):
    c, s = np.cos(k * p[:, 0]), np.sin(k * p[:, 0])
    return np.stack((c * p[:, 0] - s * p[:, 1], s * p[:, 0] + c * p[:, 1], p[:, 2]), axis=1)


def f_plane(p, normal, point):
    n = np.asarray(normal, float) / np.linalg.norm(normal)
    return (np.asarray(point) - p) @ n


def f_capped_cone(p, a, b, ra, rb):
    a, b = np.asarray(a, float), np.asarray(b, float)
    rba, baba = rb - ra, np.dot(b - a, b - a)
    papa = np.sum((p - a) ** 2, axis=1)
    paba = (p - a) @ (b - a) / baba
    x = np.sqrt(np.maximum(papa - paba * paba * baba, 0))
    cax = np.maximum(0, x - np.where(paba < 0.5, ra, rb))
    cay = np.abs(paba - 0.5) - 0.5
    f = np.clip((rba * (x - ra) + paba * baba) / (rba * rba + baba), 0, 1)
    cbx, cby = x - ra - f * rba, paba - f
    s = np.where((cbx < 0) & (cay < 0), -1, 1)
    return s * np.sqrt(np.minimum(cax * cax + cay * cay * baba, cbx * cbx + cby * cby * baba))


def rod(p, axis):
    """fogleman's cylinder(0.5).orient(axis) for an axis of the frame."""
    i = {'x': (1, 2), 'y': (0, 2), 'z': (0, 1)}[axis]
    return length(p[:, i]) - 0.5


CASES = {
    'readme': (lambda: (sphere(1) & box(1.5)) - (cylinder(0.5).orient(X) | cylinder(0.5).orient(Y) |
                                                 cylinder(0.5).orient(Z)),
               lambda p: np.maximum(np.maximum(f_sphere(p), f_box(p, 1.5)),
                                    -np.minimum(np.minimum(rod(p, 'x'), rod(p, 'y')), rod(p, 'z')))),
    'torus': (lambda: torus(1, 0.25), lambda p: f_torus(p, 1, 0.25)),
    'rotate': (lambda: box((2, 0.5, 0.5)).rotate(pi / 6, (1, 1, 0)),
               lambda p: f_box(f_rotate(p, pi / 6, (1, 1, 0)), (2, 0.5, 0.5))),
    'twist': (lambda: box((1, 0.5, 2)).twist(pi / 3),
              lambda p: f_box(f_twist(p, pi / 3), (1, 0.5, 2))),
    'bend': (lambda: box((2, 0.3, 0.3)).bend(0.5),
             lambda p: f_box(f_bend(p, 0.5), (2, 0.3, 0.3))),
    'plane': (lambda: sphere() & plane((1, 1, 1), (0.2, 0, 0)),
              lambda p: np.maximum(f_sphere(p), f_plane(p, (1, 1, 1), (0.2, 0, 0)))),
    'capped_cone': (lambda: capped_cone((0, 0, -1), (1, 1, 1), 0.6, 0.2),
                    lambda p: f_capped_cone(p, (0, 0, -1), (1, 1, 1), 0.6, 0.2)),
}


@pytest.mark.parametrize('name', sorted(CASES))
def test_our_surface_is_foglemans(name):
    shape, field = CASES[name]
    m = marchstudio.Scene(shape()).mesh(resolution=48)
    cell = max(m.report['voxel'], 1e-6)
    d = field(m.vertices.astype(np.float64))
    assert len(d) > 100
    # a bound (twist, bend, fogleman's plane cut) is not a distance: half a cell
    assert np.quantile(np.abs(d), 0.99) < 0.5 * cell, (name, np.abs(d).max(), cell)
