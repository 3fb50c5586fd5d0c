// graph_level.glsl: map()'s lookup in grid level MS_LEVEL (graph_interp.glsl
// includes it once per level, so the levels are unrolled as before: no
// #pragma once). The finest level holding p gives the list; a level's
// cells inside the next finer level are empty (never looked up, but a
// rounding error on that level's edge may land there, so an empty cell
// falls through). A far cell (outer levels only) gives the lower bound its
// centre's value and the Lipschitz bound make, or the whole program where
// that bound is under half the cell's half diagonal.
  if (count == 0u) {
    uvec4 a = msGraphCell[1 + 3 * MS_LEVEL], b = msGraphCell[2 + 3 * MS_LEVEL], d = msGraphCell[3 + 3 * MS_LEVEL];
    vec3 g = (p - uintBitsToFloat(a.xyz)) / uintBitsToFloat(b.xyz);
    if (all(greaterThanEqual(g, vec3(0.0))) && all(lessThan(g, vec3(d.xyz)))) {
      uvec3 c = min(uvec3(g), d.xyz - 1u);
      uvec4 cell = msGraphCell[MS_GRID_HEADER + a.w + c.x + d.x * (c.y + d.y * c.z)];
      start = cell.x;
      count = cell.y;
      if (cell.w >= 2u) {  // far: 2 the value at its coarse cell's centre, 3 at its own
        uint split = cell.w == 2u ? uint(MS_GRID_SPLIT) : 1u;
        vec3 size = uintBitsToFloat(b.xyz) * float(split);
        vec3 centre = uintBitsToFloat(a.xyz) + (vec3(c / split) + 0.5) * size;
        float lb = max(uintBitsToFloat(cell.x) - MS_GRAPH_L * length(p - centre), msGraphBoxDistance(p));
        // A bound near 0 would read as a hit (a shadow ray's HIT_EPSILON).
        if (lb > 0.25 * length(size)) return vec2(lb, 0.0);
        start = 0u;
        count = MS_GRAPH_LEN;
      }
    }
  }
