// A unit sphere, for the load-error files here.
vec2 map(vec3 p) { return vec2(sdSphere(p, 1.0), MAT_A); }
