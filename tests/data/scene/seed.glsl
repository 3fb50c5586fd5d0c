// Test map for the scene loader: a unit sphere resting on the plane y = 0.
// Only its existence matters to tests/unit/test_scene_*.cpp.
vec2 map(vec3 p) {
  float sphere = length(p - vec3(0.0, 1.0, 0.0)) - 1.0;
  float plane = p.y;
  return sphere < plane ? vec2(sphere, float(MAT_BALL)) : vec2(plane, float(MAT_FLOOR));
}
