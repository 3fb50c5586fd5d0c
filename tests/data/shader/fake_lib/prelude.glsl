// Stub prelude for tests: uses every define so a misspelt or ill-typed one fails to compile.
const int kMaxSteps = MAX_STEPS;
const float kMaxDist = MAX_DIST;
const float kHitTol = HIT_TOLERANCE;
const float kHitEps = HIT_EPSILON;
const float kLipschitz = LIPSCHITZ;
const int kShadowSteps = SHADOW_STEPS;
const int kAoTaps = AO_TAPS;
const int kBounces = MAX_BOUNCES;
#if ENABLE_SHADOWS + ENABLE_AO + ENABLE_REFLECTIONS + ENABLE_CHECKER_FILTER > 4
#error a flag is not 0 or 1
#endif
uniform float uMaterialTag[NUM_MATERIALS];
#if NUM_LIGHTS > 0
uniform vec4 uLightPos[NUM_LIGHTS];
#endif
layout(location = 0) out vec4 outColor;
