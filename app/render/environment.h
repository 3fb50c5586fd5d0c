// HDR environment maps for SDF scenes ([sky] environment): an
// equirectangular EXR or HDR image, seen where rays escape (the sky and
// reflections, sdf_shaders/sky.glsl with ENV_MAP) and lighting the ambient
// term by its diffuse irradiance, as 9 spherical-harmonic coefficients
// (Ramamoorthi and Hanrahan 2001) computed once at load and cached on disk
// by the file's content hash. No GL here: the map travels to the scene
// pass as a texture input named uEnvMap (render/graph.h).
//
// Directions: the image's top row is +y, its centre column faces +z and u
// grows towards +x; `rotation` turns the map about +y.
//
//   attach_environment(scene, scene_pass);   // reads the map, fills scene.sky.irradiance
#pragma once
#include <array>
#include <filesystem>
#include <string>

#include <glm/vec3.hpp>

#include "io/image.h"
#include "render/graph.h"
#include "scene/scene.h"

namespace ms {

using IrradianceSh = std::array<glm::vec3, 9>;

// E(n) / pi of an equirectangular map (RGB, top row first) as SH
// coefficients: for a constant map of radiance L it is L in every direction.
IrradianceSh irradiance_sh(const Image& equirect);
// The coefficients evaluated at unit direction n, as the shader does.
glm::vec3 eval_irradiance(const IrradianceSh& sh, glm::vec3 n);
// The map direction of pixel centre (x, y) of a w x h equirectangular image.
glm::vec3 equirect_direction(double x, double y, int w, int h);

// Where the coefficients of a file with this content hash are kept:
// cache_dir()/irradiance/<hash>.txt (io/cache_dir.h); empty with no cache.
// An entry is trusted only when it is plausible for the map read (finite,
// within what its brightest texel allows, not all zero unless the map is
// black); else it is computed again, with a warning on stderr.
std::filesystem::path irradiance_cache_path(const std::string& content_hash);

// For a scene with [sky] environment: reads the map (bad_input naming it
// when it cannot), sets scene.sky.irradiance (from the cache when the same
// bytes were seen before) and binds the map to `pass` as uEnvMap. Nothing
// for a scene without one. `from_cache`, when given, says which it was. The
// last map read is kept in memory: the same file (path, size, modification
// time) again is not read, decoded or hashed again (the viewer's reloads).
void attach_environment(Scene& scene, PassSource& pass, bool* from_cache = nullptr);

}  // namespace ms
