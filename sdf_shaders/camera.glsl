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

// The look-at basis (right, up, forward as columns) and tan(fov/2) come from
// the host (uCamBasis, uCamTanHalfFov: app/scene/camera_frame.h), computed
// once per frame. Degenerate input never yields NaN there: a zero view
// vector looks down +z, and an up parallel to the view direction is replaced
// by another axis.

// Angle subtended by one pixel at the image centre (radians, small-angle).
float pixelAngle() {
  return 2.0 * uCamTanHalfFov / max(uResolution.y, 1.0);
}

// Differential of normalize(v) given the differential dv of v (Igehy eq. 10).
vec3 normalizeDiff(vec3 v, vec3 dv) {
  float vv = dot(v, v);
  return (vv * dv - dot(v, dv) * v) / (vv * sqrt(vv));
}

// Primary ray through the sample `pix` (window coordinates, pixels; e.g.
// floor(gl_FragCoord.xy) + uPixelOffset + uJitter), pinhole look-at camera from the
// uniforms, with differentials for a one-pixel step.
Ray cameraRay(vec2 pix) {
  mat3 B = uCamBasis;
  float th = uCamTanHalfFov;
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
