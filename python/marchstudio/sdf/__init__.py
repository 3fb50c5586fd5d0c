"""fogleman/sdf's API over marchstudio's scene graph:

    from marchstudio.sdf import *
    f = sphere(1) & box(1.5)
    c = cylinder(0.5)
    f -= c.orient(X) | c.orient(Y) | c.orient(Z)
    f.save('out.stl')

Each shape is a graph node (f.to_json()); docs/python.md lists every name
and the node it becomes. Functions the graph cannot express raise
NotImplementedError saying what to use instead.
"""
from . import ease
from .core import ORIGIN, UP, X, Y, Z, SDF, pi, union, difference, intersection, blend
from .d3 import (SDF3, sphere, box, rounded_box, wireframe_box, torus, capsule, capped_cylinder,
                 rounded_cylinder, capped_cone, rounded_cone, ellipsoid, pyramid, tetrahedron,
                 octahedron, dodecahedron, icosahedron, plane, slab, cylinder, sdf3, image, text,
                 bend_linear, bend_radial, transition_linear, transition_radial, slice)
from .d2 import (SDF2, circle, rectangle, rounded_rectangle, equilateral_triangle, hexagon, rounded_x,
                 polygon, line, sdf2, extrude, extrude_to, revolve)


def _fn(name):
    def call(other, *args, **kwargs):
        return getattr(other, name)(*args, **kwargs)
    call.__name__ = name
    call.__doc__ = f"{name}(other, ...): other.{name}(...)"
    return call


translate = _fn('translate')
scale = _fn('scale')
rotate = _fn('rotate')
orient = _fn('orient')
repeat = _fn('repeat')
circular_array = _fn('circular_array')
dilate = _fn('dilate')
erode = _fn('erode')
shell = _fn('shell')
elongate = _fn('elongate')
twist = _fn('twist')
bend = _fn('bend')

__all__ = [n for n in dir() if not n.startswith('_')]
