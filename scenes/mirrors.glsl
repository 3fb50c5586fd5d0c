// mirrors.glsl: what stands between the two mirrors of mirrors.toml (the
// mirrors and the floor are declared planes, intersected exactly): a chain
// of links, an octahedron on a capped-torus stand and a solid angle. All
// exact or unions of exact shapes: lipschitz stays 1.

vec2 map(vec3 p) {
  // A chain: three links, each turned 90 degrees about its length from the last.
  vec3 c = p - vec3(-0.6, 1.9, 0.6);
  float chain = BIG;
  for (int i = 0; i < 3; ++i) {
    vec3 q = c - vec3(0.0, -0.42 * float(i), 0.0);
    if (i == 1) q = q.zyx;
    chain = min(chain, sdLink(q, 0.13, 0.16, 0.045));
  }
  vec2 d = vec2(chain, MAT_GOLD);
  // An octahedron on a stand.
  vec3 o = p - vec3(0.7, 0.0, 0.2);
  float stand = sdCappedTorus((o - vec3(0.0, 0.45, 0.0)).xzy * vec3(1.0, 1.0, -1.0), vec2(sin(2.4), cos(2.4)), 0.35, 0.04);
  stand = min(stand, sdRoundedCylinder(o - vec3(0.0, 0.05, 0.0), 0.3, 0.05, 0.02));
  d = opUnion(d, vec2(sdOctahedron(domRotateAxis(o - vec3(0.0, 0.85, 0.0), vec3(0.0, 1.0, 0.0), 0.5), 0.32), MAT_GEM));
  d = opUnion(d, vec2(stand, MAT_GOLD));
  // A sphere sector, point down.
  d = opUnion(d, vec2(sdSolidAngle((p - vec3(-0.4, 0.62, -0.5)) * vec3(1.0, -1.0, 1.0), vec2(sin(0.6), cos(0.6)), 0.6), MAT_GEM));
  return d;
}
