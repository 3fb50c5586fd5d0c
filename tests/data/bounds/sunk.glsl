// A unit ball centred on the floor: its lower half is under the plane.
vec2 map(vec3 p) {
  return vec2(sdSphere(p, 1.0), MAT_BALL);
}
