"""Every fogleman/sdf function builds a node the C++ loader accepts, each
conversion is the coverage table's (tools/coverage_rows.py), and the
functions the graph cannot express say so."""
import importlib.util
import math
import os

import numpy as np
import pytest

import marchstudio
from marchstudio.sdf import *  # noqa: F401,F403 (the API under test, as a user writes it)

ROD = capped_cylinder(-Z, Z, 0.25)

# fogleman's call for each row of tools/coverage_rows.py that has a node.
CALLS = {
    'sphere': lambda: sphere(),
    'box': lambda: box((1, 2, 3)),
    'rounded_box': lambda: rounded_box((1, 2, 3), 0.25),
    'wireframe_box': lambda: wireframe_box((1, 2, 3), 0.05),
    'torus': lambda: torus(1, 0.25),
    'capsule': lambda: capsule(-Z, Z, 0.5),
    'capped_cylinder': lambda: capped_cylinder(-Z, Z, 0.5),
    'rounded_cylinder': lambda: rounded_cylinder(0.5, 0.1, 2),
    'capped_cone': lambda: capped_cone(-Z, Z, 1, 0.5),
    'orient': lambda: ROD.orient(X) | ROD.orient(Y) | ROD.orient(Z),
    'rounded_cone': lambda: rounded_cone(0.75, 0.25, 2),
    'ellipsoid': lambda: ellipsoid((1, 2, 3)),
    'pyramid': lambda: pyramid(1),
    'tetrahedron': lambda: tetrahedron(1),
    'octahedron': lambda: octahedron(1),
    'dodecahedron': lambda: dodecahedron(1),
    'icosahedron': lambda: icosahedron(1),
    'plane': lambda: sphere() & plane(),
    'slab': lambda: sphere() & slab(z0=-0.5, z1=0.5, x0=0),
    'cylinder': lambda: sphere() - cylinder(0.5),
    'translate': lambda: sphere().translate((0, 0, 2)),
    'scale': lambda: sphere().scale(2),
    'scale (tuple)': lambda: sphere().scale((1, 2, 3)),
    'rotate': lambda: capped_cylinder(-Z, Z, 0.5).rotate(pi / 4, X),
    'union': lambda: box((3, 3, 0.5)) | sphere(),
    'difference': lambda: box((3, 3, 0.5)) - sphere(),
    'intersection': lambda: box((3, 3, 0.5)) & sphere(),
    'smooth_union': lambda: union(box((3, 3, 0.5)), sphere(), k=0.25),
    'smooth_difference': lambda: difference(box((3, 3, 0.5)), sphere(), k=0.25),
    'smooth_intersection': lambda: intersection(box((3, 3, 0.5)), sphere(), k=0.25),
    'repeat': lambda: sphere().repeat(3, (1, 1, 0)),
    'circular_array': lambda: capped_cylinder(-Z, Z, 0.5).circular_array(8, 4),
    'blend': lambda: sphere().blend(box()),
    'dilate': lambda: box().dilate(0.1),
    'erode': lambda: box().erode(0.1),
    'shell': lambda: sphere().shell(0.05) & plane(-Z),
    'elongate': lambda: sphere(0.5).elongate((0.25, 0.5, 0.75)),
    'twist': lambda: box().twist(pi / 2),
    'bend': lambda: box().bend(1),
    'extrude': lambda: hexagon(1).extrude(1),
    'revolve': lambda: hexagon(1).revolve(3),
    'circle': lambda: circle(1).extrude(0.2),
    'rectangle': lambda: rectangle((2, 1)).extrude(0.2),
    'rounded_rectangle': lambda: rounded_rectangle((2, 1), 0.25).extrude(0.2),
    'equilateral_triangle': lambda: equilateral_triangle().extrude(0.2),
    'hexagon': lambda: hexagon(1).extrude(0.2),
    'rounded_x': lambda: rounded_x(2, 0.2).extrude(0.2),
    'polygon': lambda: polygon([(-1, -0.4), (0.2, -0.4), (0.2, -0.9), (1, 0), (0.2, 0.9), (0.2, 0.4), (-1, 0.4)]).extrude(0.2),
}


def rows():
    spec = importlib.util.spec_from_file_location('coverage_rows', os.path.join(
        os.path.dirname(__file__), '..', '..', 'tools', 'coverage_rows.py'))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod.ROWS


def close(a, b, path='root'):
    """Nodes equal, numbers within 1e-5 (the table rounds to six places)."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and set(a) == set(b), f"{path}: keys {sorted(a)} != {sorted(b)}"
        for k in a:
            close(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), f"{path}: {a} != {b}"
        for i, (x, y) in enumerate(zip(a, b)):
            close(x, y, f"{path}/{i}")
    elif isinstance(a, (int, float)) and not isinstance(a, bool) and a is not None:
        assert isinstance(b, (int, float)) and abs(a - b) <= 1e-5, f"{path}: {a} != {b}"
    else:
        assert a == b, f"{path}: {a!r} != {b!r}"


@pytest.mark.parametrize('name', sorted(CALLS))
def test_node_is_the_coverage_tables(name):
    table = {r[1]: r[3] for r in rows() if r[3] is not None}
    # The table shows a profile as a thin plate, h 0.2, as CALLS builds it.
    close(CALLS[name]().to_node(), table[name])


def test_every_row_with_a_node_has_a_call():
    named = {r[1] for r in rows() if r[3] is not None}
    assert named == set(CALLS)


@pytest.mark.parametrize('name', sorted(CALLS))
def test_the_loader_accepts_it(name, tmp_path):
    scene = marchstudio.Scene(CALLS[name]())
    lo, hi = scene.box()
    assert all(a < b for a, b in zip(lo, hi))


def test_orient_turns_as_fogleman():
    # rotate_to(UP, axis): round cross(axis, Z) by acos(axis . Z)
    assert ROD.orient(X).to_node()['rotate'] == [0, -1, 0, 90]
    assert ROD.orient(Y).to_node()['rotate'] == [1, 0, 0, 90]
    assert 'rotate' not in ROD.orient(Z).to_node()
    assert ROD.orient(-Z).to_node()['rotate'] == [0, 1, 0, 180]


def test_transforms_compose_into_one_similarity():
    one = sphere().translate((1, 0, 0)).rotate(pi / 2, Z).scale(2).to_node()
    # one turn stays a rotate key: scale, then rotate, then translate
    assert one['rotate'] == [0, 0, 1, 90] and one['scale'] == 2 and one['translate'] == [0, 2, 0]
    two = sphere().translate((1, 0, 0)).rotate(pi / 2, Z).rotate(pi / 2, X).scale(2).to_node()
    m = np.array(two['matrix']).reshape(3, 4)
    # the centre went (1,0,0) -> (0,1,0) -> (0,0,1) -> (0,0,2); the radius doubled
    assert np.allclose(m[:, 3], (0, 0, 2), atol=1e-9)
    assert np.allclose(m[:, :3] @ (1, 0, 0), (0, 0, 2), atol=1e-9)


def test_k_applies_to_the_right_operand_as_fogleman():
    f = sphere() | box().k(0.2)
    assert f.to_node()['op'] == 'opSmoothUnion' and f.to_node()['k'] == 0.2
    # a chain folds left into one node's children
    g = sphere() | box() | torus(1, 0.2)
    assert g.to_node()['op'] == 'opUnion' and len(g.to_node()['children']) == 3


@pytest.mark.parametrize('call, word', [
    (lambda: sdf3(lambda p: p), 'sdf3'),
    (lambda: image('x.png'), 'image'),
    (lambda: text('font.ttf', 'hi'), 'text'),
    (lambda: slice(sphere()), 'slice'),
    (lambda: sphere().bend_linear(-Z, Z, X), 'bend_linear'),
    (lambda: sphere().bend_radial(1, 2, 1), 'bend_radial'),
    (lambda: transition_linear(sphere(), box()), 'transition_linear'),
    (lambda: circle().extrude_to(rectangle(), 1), 'extrude_to'),
    (lambda: line(), 'line'),
    (lambda: polygon([(math.cos(i / 6), math.sin(i / 6)) for i in range(33)]), 'polygon'),
    (lambda: slab(z0=0, k=0.1), 'slab'),
])
def test_what_the_graph_cannot_express_says_so(call, word):
    with pytest.raises(NotImplementedError, match=word):
        call()


def test_bad_arguments_are_value_errors():
    with pytest.raises(ValueError, match='radius'):
        sphere(radius=(1, 2))
    with pytest.raises(ValueError, match='scale'):
        sphere().scale(0)
    with pytest.raises(ValueError, match='2D'):
        marchstudio.Scene(circle())


def test_polygon_takes_its_points_once_as_sd2polygon():
    n = polygon([(0, 0), (1, 0), (1, 1), (1, 1), (0, 1), (0, 0)]).to_node()
    assert n == {'sdf': 'sd2Polygon', 'v': [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]}
    with pytest.raises(ValueError, match='3 or more'):
        polygon([(0, 0), (1, 0), (0, 0)])


def test_triangle_polygon_is_sd2triangle():
    n = polygon([(0, 0), (1, 0), (0, 1)]).to_node()
    assert n == {'sdf': 'sd2Triangle', 'a': [0.0, 0.0], 'b': [1.0, 0.0], 'c': [0.0, 1.0]}
