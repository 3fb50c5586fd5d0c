"""The rows of docs/scene-graph.md's "Coverage against fogleman/sdf": one per
function of fogleman/sdf's README "Function Reference", in its order.

Each row is (group, fogleman's name, its signature, our node or None,
notes). A node
is in fogleman's Z-up coordinates, so points, sizes and axes carry over
unchanged; tools/coverage.py stands it up in our Y-up scene for its
picture. A row without a node is left out, and its notes say why and what
would be needed. Read by tools/coverage.py only.
"""

Z_TO_Y = [1, 0, 0, 90]  # our y axis onto fogleman's z: for the shapes we build round y
INV_SQRT3 = 0.57735


def sdf(name, **params):
    return dict(sdf=name, **params)


def op(name, children, **params):
    return dict(op=name, **params, children=children)


def flat(profile):
    """A 2D profile as a thin plate, the solid its row shows."""
    return op('extrude', [profile], h=0.2)


SPHERE = sdf('sdSphere', r=1)
CUBE = sdf('sdBox', b=[0.5, 0.5, 0.5])
SLAB_A = sdf('sdBox', b=[1.5, 1.5, 0.25])  # the README's a = box((3, 3, 0.5)); b is sphere()
ROD = sdf('sdCappedCylinder', a=[0, 0, -1], b=[0, 0, 1], r=0.25)
TETRA = op('opIntersection', [sdf('sdBox', b=[1, 1, 1])] + [
    sdf('sdPlane', n=[x * INV_SQRT3, y * INV_SQRT3, z * INV_SQRT3], w=-INV_SQRT3)
    for x, y, z in ((1, 1, -1), (-1, -1, -1), (1, -1, 1), (-1, 1, 1))])
BLENDS = ('fogleman\'s smooth operators are the same quadratic smooth minimum as ours (Quilez\'s, '
          'written another way): `k` carries over')
EASING = 'we have no easing functions, so `e` would be a name from a fixed list'
DOMAIN_BOUND = 'its box found from the child\'s and its Lipschitz bound'

ROWS = [
    ('3D primitives', 'sphere', 'sphere(radius=1, center=ORIGIN)', SPHERE,
     '`radius` is `r`; `center` is a `translate`.'),
    ('3D primitives', 'box', 'box(size=1, center=ORIGIN, a=None, b=None)', sdf('sdBox', b=[0.5, 1, 1.5]),
     '`box((1, 2, 3))`: `size` is full side lengths, `b` half extents; `center` is a `translate`; '
     'corners `a`, `b` are `b` = (b - a) / 2 translated to (a + b) / 2.'),
    ('3D primitives', 'rounded_box', 'rounded_box(size, radius)', sdf('sdRoundBox', b=[0.5, 1, 1.5], r=0.25),
     '`rounded_box((1, 2, 3), 0.25)`: `b` = `size` / 2, rounding included in both; `r` = `radius`.'),
    ('3D primitives', 'wireframe_box', 'wireframe_box(size, thickness)', sdf('sdBoxFrame', b=[0.525, 1.025, 1.525], e=0.025),
     '`wireframe_box((1, 2, 3), 0.05)`: fogleman\'s bars are centred on the edges of `size`, ours lie '
     'inside `b`: `b` = (`size` + `thickness`) / 2, `e` = `thickness` / 2.'),
    ('3D primitives', 'torus', 'torus(r1, r2)', sdf('sdTorus', t=[1, 0.25], rotate=Z_TO_Y),
     '`t` = [`r1`, `r2`]; ours lies round y, fogleman\'s round z: `rotate` [1, 0, 0, 90].'),
    ('3D primitives', 'capsule', 'capsule(a, b, radius)', sdf('sdCapsule', a=[0, 0, -1], b=[0, 0, 1], r=0.5),
     'The same parameters: `capsule(-Z, Z, 0.5)`.'),
    ('3D primitives', 'capped_cylinder', 'capped_cylinder(a, b, radius)',
     sdf('sdCappedCylinder', a=[0, 0, -1], b=[0, 0, 1], r=0.5),
     'The same parameters: `capped_cylinder(-Z, Z, 0.5)`.'),
    ('3D primitives', 'rounded_cylinder', 'rounded_cylinder(ra, rb, h)', sdf('sdRoundedCylinder', r=0.5, h=1, e=0.1, rotate=Z_TO_Y),
     '`rounded_cylinder(0.5, 0.1, 2)`: `r` = `ra`, `e` = `rb` (the rims\' radius), `h` = `h` / 2 (ours is '
     'a half height); round y, so `rotate` onto z.'),
    ('3D primitives', 'capped_cone', 'capped_cone(a, b, ra, rb)', sdf('sdCappedCone', h=1, r1=1, r2=0.5, rotate=Z_TO_Y),
     '`capped_cone(-Z, Z, 1, 0.5)`: ours is centred on y, radius `r1` at -`h`: `h` = length(b - a) / 2, '
     '`r1` = `ra`, `r2` = `rb`, then `rotate` y onto b - a and `translate` to (a + b) / 2.'),
    ('3D primitives', 'rounded_cone', 'rounded_cone(r1, r2, h)', sdf('sdRoundCone', r1=0.75, r2=0.25, h=2, rotate=Z_TO_Y),
     'The same parameters; ours rises along y: `rotate` [1, 0, 0, 90].'),
    ('3D primitives', 'ellipsoid', 'ellipsoid(size)', sdf('sdEllipsoid', r=[1, 2, 3]),
     '`size` is the semi-axes, `r`; the same bound.'),
    ('3D primitives', 'pyramid', 'pyramid(h)', sdf('sdPyramid', h=1, rotate=Z_TO_Y),
     'Both have a unit square base at the origin and the apex at `h`; ours along y: `rotate`.'),
    ('Platonic solids', 'tetrahedron', 'tetrahedron(r)', TETRA,
     'No primitive. fogleman\'s ignores `r`: the tetrahedron with corners (1, 1, 1), (1, -1, -1), '
     '(-1, 1, -1), (-1, -1, 1), whose field is the largest of its four face planes\' distances; the '
     'same planes intersected here, with the cube round it to bound them (same surface). `scale` for '
     'another size.'),
    ('Platonic solids', 'octahedron', 'octahedron(r)', sdf('sdOctahedron', s=1),
     '`s` = `r`, the corners\' distance. fogleman\'s is a bound, ours exact: the same solid.'),
    ('Platonic solids', 'dodecahedron', 'dodecahedron(r)', sdf('sdDodecahedron', r=0.850651, rotate=[0, 0, 1, 90]),
     'Ours takes the inradius, 0.850651 `r`; fogleman\'s faces are ours turned 90 degrees round z. '
     'The same bound.'),
    ('Platonic solids', 'icosahedron', 'icosahedron(r)', sdf('sdIcosahedron', r=0.934172, rotate=[0, 0, 1, 90]),
     'Ours takes the inradius, 0.934172 `r`; turned 90 degrees round z as the dodecahedron. '
     'The same bound.'),
    ('Infinite 3D primitives', 'plane', 'plane(normal=UP, point=ORIGIN)',
     op('opIntersection', [SPHERE, sdf('sdPlane', n=[0, 0, -1], w=0)]),
     '`sphere() & plane()`: fogleman keeps the side `normal` points to, ours the other: `n` = '
     '-`normal`, `w` = dot(`point`, `normal`). Unbounded: only in an intersection or a subtraction\'s cut.'),
    ('Infinite 3D primitives', 'slab', 'slab(x0=None, y0=None, z0=None, x1=None, y1=None, z1=None, k=None)',
     op('opIntersection', [SPHERE, sdf('sdSlab', z=[-0.5, 0.5], x=[0, None])]),
     '`sphere() & slab(z0=-0.5, z1=0.5, x0=0)`: `x` = [`x0`, `x1`], `None` is `null`. Ours is exact '
     'at the corners, fogleman\'s the planes\' intersection; its `k` (blended corners) has no counterpart.'),
    ('Infinite 3D primitives', 'cylinder', 'cylinder(radius)',
     op('opSubtraction', [SPHERE, sdf('sdInfiniteCylinder', c=[0, 0, 0.5], rotate=Z_TO_Y)]),
     '`sphere() - cylinder(0.5)`: ours runs along y through (c.x, 0, c.y) with radius c.z: `c` = '
     '[0, 0, `radius`], `rotate` onto z.'),
    ('Positioning', 'translate', 'translate(other, offset)', sdf('sdSphere', r=1, translate=[0, 0, 2]),
     '`translate` on any node.'),
    ('Positioning', 'scale', 'scale(other, factor)', sdf('sdSphere', r=1, scale=2),
     'A number: `scale` on any node, exact.'),
    ('Positioning', 'scale (tuple)', 'scale(other, factor)', op('scale', [SPHERE], s=[1, 2, 3]),
     'A tuple: the `scale` modifier. Both multiply the child\'s value by the smallest factor, a bound.'),
    ('Positioning', 'rotate', 'rotate(other, angle, vector=Z)', dict(ROD, r=0.5, rotate=[1, 0, 0, 45]),
     '`rotate(pi / 4, X)`: `rotate` [`vector`, degrees], radians to degrees; both turn the shape '
     'right-handed.'),
    ('Positioning', 'orient', 'orient(other, axis)',
     op('opUnion', [dict(ROD, rotate=[0, -1, 0, 90]), dict(ROD, rotate=[1, 0, 0, 90]), ROD]),
     '`c.orient(X) | c.orient(Y) | c.orient(Z)`: `rotate` [cross(axis, Z), acos(dot(axis, Z)) in degrees], as '
     'fogleman\'s code turns, which takes +z to -`axis` (its README says +`axis`; the same for a '
     'shape symmetric end to end, as here).'),
    ('Boolean operations', 'union', 'union(a, *bs, k=None)', op('opUnion', [SLAB_A, SPHERE]),
     '`a | b`; several `bs` are more children, folded left as fogleman folds them.'),
    ('Boolean operations', 'difference', 'difference(a, *bs, k=None)', op('opSubtraction', [SLAB_A, SPHERE]),
     '`a - b`: the first child minus the rest.'),
    ('Boolean operations', 'intersection', 'intersection(a, *bs, k=None)', op('opIntersection', [SLAB_A, SPHERE]),
     '`a & b`.'),
    ('Boolean operations', 'smooth_union', 'union(a, *bs, k=0.25)', op('opSmoothUnion', [SLAB_A, SPHERE], k=0.25),
     BLENDS + '.'),
    ('Boolean operations', 'smooth_difference', 'difference(a, *bs, k=0.25)', op('opSmoothSubtraction', [SLAB_A, SPHERE], k=0.25),
     'As smooth_union.'),
    ('Boolean operations', 'smooth_intersection', 'intersection(a, *bs, k=0.25)',
     op('opSmoothIntersection', [SLAB_A, SPHERE], k=0.25),
     'As smooth_union.'),
    ('Repetition', 'repeat', 'repeat(other, spacing, count=None, padding=0)',
     op('repeat', [SPHERE], spacing=[3, 3, 3], count=[1, 1, 0]),
     '`sphere().repeat(3, (1, 1, 0))`: a number `spacing` is ours on every axis; `count` copies either side, '
     '`None` left out (no end). No `padding`: ours looks at every copy that may be nearest.'),
    ('Repetition', 'circular_array', 'circular_array(other, count, offset)',
     op('polar', [dict(ROD, r=0.5)], count=8, radius=4, axis=[0, 0, 1]),
     '`polar`: `count`, `radius` = `offset`, `axis` z; both move the first copy out along +x.'),
    ('Miscellaneous', 'blend', 'blend(a, *bs, k=0.5)', op('opBlend', [SPHERE, CUBE], t=0.5),
     '`sphere().blend(box())`: `t` = `k`.'),
    ('Miscellaneous', 'dilate', 'dilate(other, r)', op('dilate', [CUBE], r=0.1),
     'The same `r` (a box here; the README dilates its CSG example).'),
    ('Miscellaneous', 'erode', 'erode(other, r)', op('erode', [CUBE], r=0.1), 'The same `r`.'),
    ('Miscellaneous', 'shell', 'shell(other, thickness)',
     op('opIntersection', [op('shell', [SPHERE], thickness=0.05), sdf('sdPlane', n=[0, 0, 1], w=0)]),
     '`sphere().shell(0.05) & plane(-Z)`: both take the full thickness (the library\'s `onion` a half).'),
    ('Miscellaneous', 'elongate', 'elongate(other, size)', op('elongate', [sdf('sdSphere', r=0.5)], h=[0.25, 0.5, 0.75]),
     '`h` = `size`: both insert twice it at the centre.'),
    ('Miscellaneous', 'twist', 'twist(other, k)', op('twist', [CUBE], k=-1.5708, axis=[0, 0, 1]),
     '`box().twist(pi / 2)`: fogleman turns the point by +k z, ours by -k z, so `k` = -`k`; '
     '`axis` z (ours defaults to y).'),
    ('Miscellaneous', 'bend', 'bend(other, k)', op('bend', [CUBE], k=1),
     'The same `k`, plane and sense: p.xy turned by k x.'),
    ('Miscellaneous', 'bend_linear', 'bend_linear(other, p0, p1, v, e=ease.linear)', None,
     'The shape moved by `v` e(t), t the clamped position along `p0`-`p1`: a shear no modifier does. '
     'Needs a `bend_linear` domain map (`p0`, `p1`, `v`, `e`), ' + DOMAIN_BOUND + ' 1 + length(v) max(e\') '
     '/ length(p1 - p0); ' + EASING + '.'),
    ('Miscellaneous', 'bend_radial', 'bend_radial(other, r0, r1, dz, e=ease.linear)', None,
     'The shape moved along z by `dz` e(t), t the clamped radius from `r0` to `r1`. Needs a `bend_radial` domain map, '
     'its box the child\'s moved by up to `dz` along z and its bound 1 + abs(dz) max(e\') / (r1 - r0); '
     + EASING + '.'),
    ('Miscellaneous', 'transition_linear', 'transition_linear(f0, f1, p0=-Z, p1=Z, e=ease.linear)', None,
     'A blend whose weight e(t) varies along `p0`-`p1`, where `opBlend`\'s `t` is one number and a '
     'combinator sees only its children\'s values, not the point. Needs a two-child node that reads '
     'p; its slope gains abs(f1 - f0) max(e\') / length(p1 - p0), which grows without limit away from the '
     'surfaces, so it must be floored outside its box as `twist` is.'),
    ('Miscellaneous', 'transition_radial', 'transition_radial(f0, f1, r0=0, r1=1, e=ease.linear)', None,
     'A blend whose weight e(t) varies with the radius from `r0` to `r1`: it needs the two-child node '
     'that reads p of transition_linear, floored outside its box the same way.'),
    ('2D to 3D operations', 'extrude', 'extrude(other, h)', op('extrude', [sdf('sd2Hexagon', r=1)], h=1),
     '`hexagon(1).extrude(1)`: `h` is the full height in both; ours may round the edges (`r`).'),
    ('2D to 3D operations', 'extrude_to', 'extrude_to(a, b, h, e=ease.linear)', None,
     'Two profiles mixed along z, a + (b - a) e(z / h + 1/2). Needs an extrude of two profiles with '
     'a weight that reads z, and the same floor as transition_linear for its slope abs(b - a) max(e\') / h.'),
    ('2D to 3D operations', 'revolve', 'revolve(other, offset=0)',
     op('revolve', [sdf('sd2Hexagon', r=1)], offset=3, rotate=Z_TO_Y),
     '`hexagon(1).revolve(3)`: the same `offset`, the profile\'s y the height; ours sweeps round y, '
     'fogleman\'s round z: `rotate` [1, 0, 0, 90].'),
    ('3D to 2D operations', 'slice', 'slice(other)', None,
     'A solid\'s section at z = 0 as a profile. Profiles are 2D primitives and their combinators only; '
     'a slice needs a profile node holding a 3D subtree evaluated at (x, y, 0): the builder and the '
     'code generators going from a 2D frame back to a 3D one. fogleman\'s is not a distance either '
     '(a 1e-9 slab intersected).'),
    ('2D primitives', 'circle', 'circle(radius=1, center=ORIGIN)', flat(sdf('sd2Circle', r=1)),
     '`r` = `radius`; `center` is a 2D `translate`. Shown extruded, as every profile here.'),
    ('2D primitives', 'line', 'line(normal=UP, point=ORIGIN)', None,
     'A half-plane: there is no 2D one (`sdPlane` and `sdSlab` are solids). Needs an `sd2Plane` '
     'profile (`n`, `w`) with an infinite box, refused unbounded as the 3D half-spaces are; '
     'meanwhile cut the extruded solid with an `sdPlane` whose normal lies in xy.'),
    ('2D primitives', 'rectangle', 'rectangle(size=1, center=ORIGIN, a=None, b=None)', flat(sdf('sd2Box', b=[1, 0.5])),
     '`rectangle((2, 1))`: `b` = `size` / 2; `center`, `a`, `b` as box\'s.'),
    ('2D primitives', 'rounded_rectangle', 'rounded_rectangle(size, radius, center=ORIGIN)',
     flat(sdf('sd2RoundBox', b=[1, 0.5], r=0.25)),
     '`b` = `size` / 2, `r` = `radius`; a radius per corner (a 4-tuple) has no counterpart.'),
    ('2D primitives', 'equilateral_triangle', 'equilateral_triangle()', flat(sdf('sd2EquilateralTriangle', r=1.154701)),
     'fogleman\'s has side 2, apex up, centred: circumradius `r` = 2 / sqrt 3.'),
    ('2D primitives', 'hexagon', 'hexagon(r)', flat(sdf('sd2Hexagon', r=1)),
     '`r` is the apothem in both, flat sides at y = +-r.'),
    ('2D primitives', 'rounded_x', 'rounded_x(w, r)',
     flat(op('round', [op('opUnion', [sdf('ud2Segment', a=[-1, -1], b=[1, 1]),
                                      sdf('ud2Segment', a=[-1, 1], b=[1, -1])])], r=0.2)),
     '`rounded_x(2, 0.2)`: no primitive, but it is exactly two crossed segments from -w/2 to w/2 on '
     'the diagonals, rounded by `r`.'),
    ('2D primitives', 'polygon', 'polygon(points)',
     flat(sdf('sd2Polygon', v=[[-1, -0.4], [0.2, -0.4], [0.2, -0.9], [1, 0], [0.2, 0.9], [0.2, 0.4], [-1, 0.4]])),
     '`points` is `v`: 3 to 32 [x, y] vertices in order, either winding, each given once (the '
     'polygon closes itself); a simple polygon, exact inside and out.'),
]
