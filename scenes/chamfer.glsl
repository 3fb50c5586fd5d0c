// chamfer.glsl: a pavilion built from boxes and the seam blends of
// combinators.glsl: a stepped plinth whose steps meet in chamfers, walls
// with grooved courses and a tongue under the eaves, doorways cut with
// rounded edges, corner pillars joined to the walls by columns, and a gabled
// roof whose ridge and edges are chamfered. The seam blends are
// sqrt 2-Lipschitz where the surfaces they join do not meet at right angles
// (near box corners), so chamfer.toml sets lipschitz = 1.42.

const vec2 kSlope = vec2(0.4472136, 0.8944272);   // the roof's normal in (|z|, y): a 1 in 2 pitch

vec2 map(vec3 p) {
  // Plinth: three steps, each chamfered into the next.
  float plinth = sdBox(p - vec3(0.0, 0.1, 0.0), vec3(2.6, 0.1, 2.0));
  plinth = opUnionChamfer(plinth, sdBox(p - vec3(0.0, 0.3, 0.0), vec3(2.3, 0.1, 1.7)), 0.08);
  plinth = opUnionChamfer(plinth, sdBox(p - vec3(0.0, 0.5, 0.0), vec3(2.0, 0.1, 1.4)), 0.08);

  // Walls: a hollow box, with mortar courses grooved in every 0.3 and a
  // tongue under the eaves.
  vec3 w = p - vec3(0.0, 1.35, 0.0);
  float walls = opSubtraction(sdBox(w, vec3(1.7, 0.75, 1.1)), sdBox(w, vec3(1.5, 0.9, 0.9)));
  walls = opGroove(walls, domRepeat(w.y, 0.3), 0.02, 0.015);
  walls = opTongue(walls, w.y - 0.62, 0.05, 0.05);
  // Doorways through the long walls and the ends, their edges rounded.
  float doors = min(sdBox(w - vec3(0.0, -0.25, 0.0), vec3(0.35, 0.5, 1.5)),
                    sdBox(w - vec3(0.0, -0.3, 0.0), vec3(2.0, 0.45, 0.3)));
  walls = opSubtractionRound(walls, doors, 0.06);

  // Corner pillars, joined to the walls by three columns each.
  vec3 c = vec3(abs(p.x) - 1.72, p.y - 1.35, abs(p.z) - 1.12);
  float pillars = sdBox(c, vec3(0.16, 0.8, 0.16));
  float building = opUnionColumns(walls, pillars, 0.12, 3.0);
  building = opUnionChamfer(building, plinth, 0.06);

  // Roof: a slab 0.12 thick under two sloped planes whose ridge is
  // chamfered, cut to length by a box with chamfered edges.
  vec3 r = p - vec3(0.0, 2.1, 0.0);
  float front = dot(vec2(r.z, r.y), kSlope) - 0.4, back = dot(vec2(-r.z, r.y), kSlope) - 0.4;
  float gable = opIntersectionChamfer(front, back, 0.1);
  float roof = opIntersectionChamfer(opOnion(gable + 0.06, 0.06), sdBox(r, vec3(1.95, 0.7, 1.45)), 0.04);

  vec2 d = opUnion(vec2(building, MAT_STONE), vec2(roof, MAT_ROOF));
  return opUnion(d, vec2(plinth, MAT_STEPS));
}
