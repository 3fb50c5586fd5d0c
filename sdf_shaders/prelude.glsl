// prelude.glsl: the host <-> shader contract (uniforms, structs) and small
// helpers every other library file may use. Included by the root right after
// the host's #defines. See docs/shader-library.md.
#pragma once

// The host must emit these; fail loudly rather than guess a default.
#if !defined(NUM_LIGHTS) || !defined(NUM_MATERIALS) || !defined(MAX_STEPS) || !defined(MAX_DIST)
#error "marchstudio: NUM_LIGHTS, NUM_MATERIALS, MAX_STEPS and MAX_DIST must be defined by the host"
#endif
#if !defined(HIT_TOLERANCE) || !defined(HIT_EPSILON) || !defined(LIPSCHITZ) || !defined(MAX_BOUNCES)
#error "marchstudio: HIT_TOLERANCE, HIT_EPSILON, LIPSCHITZ and MAX_BOUNCES must be defined by the host"
#endif
#if !defined(SHADOW_STEPS) || !defined(AO_TAPS) || !defined(ENABLE_SHADOWS) || !defined(ENABLE_AO)
#error "marchstudio: SHADOW_STEPS, AO_TAPS, ENABLE_SHADOWS and ENABLE_AO must be defined by the host"
#endif
#if !defined(ENABLE_REFLECTIONS) || !defined(ENABLE_CHECKER_FILTER)
#error "marchstudio: ENABLE_REFLECTIONS and ENABLE_CHECKER_FILTER must be defined by the host"
#endif

// ---- specialization (docs/specialization.md): absent means the generic shader ----
#ifndef SPECIALIZED
#define SPECIALIZED 0           // 1: the host derived the defines below from the scene's features
#endif
#ifndef LIGHT_UNIFORMS
#define LIGHT_UNIFORMS 1        // 0: the host folded the lights into constant tables
#endif
#ifndef MATERIAL_UNIFORMS
#define MATERIAL_UNIFORMS 1     // 0: the host generated sceneMaterial() with constants
#endif
#ifndef SKY_UNIFORMS
#define SKY_UNIFORMS 1          // 0: uSkyHorizon, uSkyZenith, uAmbient are host constants
#endif

// ---- uniforms (exactly as in notes/glsl_contract.md) ----
uniform vec2  uResolution;   // full image size in pixels
uniform vec2  uJitter;       // sub-pixel sample position in [0,1)^2
uniform vec2  uPixelOffset;  // a tile's lower-left pixel in the whole image (render/tiled_still.h); 0 untiled
uniform float uTime;         // scene seconds
uniform int   uFrame;
uniform vec3  uCamPos;
uniform vec3  uCamTarget;
uniform vec3  uCamUp;
uniform float uFovY;         // vertical field of view, radians
uniform mat3  uCamBasis;     // columns: right, up, forward (unit; the host's camera_frame())
uniform float uCamTanHalfFov;  // tan(uFovY / 2), fov kept inside (0, pi)
#if SKY_UNIFORMS               // otherwise the host folded them into constants of these names
uniform vec3  uSkyHorizon;
uniform vec3  uSkyZenith;
uniform vec3  uAmbient;      // ambient light intensity Ia
#endif

struct Light {
  vec4  pos;    // w = 1: point light at xyz;  w = 0: directional, xyz = unit direction the light TRAVELS
  vec3  color;  // colour * intensity
  float size;   // point: radius (world units); directional: angular RADIUS in radians
  vec3  atten;  // point: 1/(atten.x + atten.y*d + atten.z*d*d); ignored for directional
};
#if NUM_LIGHTS > 0 && LIGHT_UNIFORMS
uniform Light uLights[NUM_LIGHTS];
#endif

struct Material {
  vec3  color;          // albedo
  float ka, kd, ks;     // Blinn-Phong ambient, diffuse, specular coefficients
  float shininess;
  float reflectivity;   // Fresnel-Schlick F0; 0 = not reflective
  int   pattern;        // 0 = plain, 1 = checker
  vec3  color2;         // second checker colour
  float patternScale;   // checker cell size (world units)
  vec3  patternVelocity;// checker offset per second
};
#if MATERIAL_UNIFORMS
uniform Material uMaterials[NUM_MATERIALS];
#endif

#if !defined(FIELD_SAMPLER)  // the mesh exporter's compute pass (field_sample.glsl) has no outputs
layout(location = 0) out vec4 outColor;   // linear HDR radiance of this sample; alpha: main.frag
#endif

// ---- library tunables: not in the contract; defaults unless #defined before this file ----
#ifndef NORMAL_EPS_MIN
#define NORMAL_EPS_MIN 1e-4     // floor of the normal epsilon (world units)
#endif
#ifndef SHADOW_MIN_STEP
#define SHADOW_MIN_STEP 2e-3    // shadow rays never step less than this (no stalling)
#endif
#ifndef SHADOW_MAX_STEP
#define SHADOW_MAX_STEP 0.5     // nor more, so the penumbra estimator sees thin occluders
#endif
#ifndef AO_RADIUS
#define AO_RADIUS 0.13          // farthest AO tap along the normal (Quilez: 0.01 + 0.12)
#endif
#ifndef FADE_START
#define FADE_START 0.6          // fraction of MAX_DIST where hits start fading into the sky
#endif

#include "common.glsl"          // constants and pure helpers, shared with Shadertoy code
