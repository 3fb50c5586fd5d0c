// camera.glsl: primary rays and their ray differentials (Igehy 1999).
#pragma once

// A ray with its differentials: how origin and (unit) direction change per
// one-pixel step in x and y. Carried through reflections to size texture
// filters and hit tolerances (never fwidth(), which breaks at silhouettes).
struct Ray {
  vec3 o, d;          // origin, unit direction
  vec3 dOdx, dOdy;    // d(origin)/d(pixel)
  vec3 dDdx, dDdy;    // d(direction)/d(pixel); perpendicular to d
};

// Look-at basis (right, up, forward) as matrix columns. Degenerate input never
// yields NaN: a zero view vector looks down +z, and an up parallel to the view
// direction is replaced by another axis.
mat3 cameraBasis(vec3 pos, vec3 target, vec3 upHint) {
  vec3 fw = safeNormalize(target - pos, vec3(0.0, 0.0, 1.0));
  vec3 up = safeNormalize(upHint, vec3(0.0, 1.0, 0.0));
  if (abs(dot(fw, up)) > 0.9999)
    up = abs(fw.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
  vec3 right = normalize(cross(fw, up));
  return mat3(right, cross(right, fw), fw);
}

// tan(fov/2) with the fov kept inside (0, pi).
float cameraTanHalfFov() {
  return tan(0.5 * clamp(uFovY, 1e-4, PI - 1e-3));
}

// Angle subtended by one pixel at the image centre (radians, small-angle).
float pixelAngle() {
  return 2.0 * cameraTanHalfFov() / max(uResolution.y, 1.0);
}

// Differential of normalize(v) given the differential dv of v (Igehy eq. 10).
vec3 normalizeDiff(vec3 v, vec3 dv) {
  float vv = dot(v, v);
  return (vv * dv - dot(v, dv) * v) / (vv * sqrt(vv));
}

// Primary ray through the sample `pix` (window coordinates, pixels; e.g.
// floor(gl_FragCoord.xy) + uJitter), pinhole look-at camera from the
// uniforms, with differentials for a one-pixel step.
Ray cameraRay(vec2 pix) {
  mat3 B = cameraBasis(uCamPos, uCamTarget, uCamUp);
  float th = cameraTanHalfFov();
  float invH = 1.0 / max(uResolution.y, 1.0);
  vec2 uv = (2.0 * pix - uResolution) * invH;     // y in [-1,1], x scaled by aspect
  vec3 v = B[2] + th * (uv.x * B[0] + uv.y * B[1]); // |v| >= 1: never zero
  float s = 2.0 * th * invH;                        // d(uv)/d(pixel) * tan
  Ray r;
  r.o = uCamPos;
  r.d = normalize(v);
  r.dOdx = vec3(0.0);
  r.dOdy = vec3(0.0);
  r.dDdx = normalizeDiff(v, s * B[0]);
  r.dDdy = normalizeDiff(v, s * B[1]);
  return r;
}

// Width of the ray's one-pixel footprint at distance t, measured across the
// ray (not projected onto a surface). The hit tolerance, normal epsilon and
// surface offsets all scale with it.
float rayFootprint(Ray r, float t) {
  return max(length(perpTo(r.dOdx, r.d) + t * r.dDdx),
             length(perpTo(r.dOdy, r.d) + t * r.dDdy));
}
