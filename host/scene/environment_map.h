// environment_map.h — an environment light as the device reads it
// (Environment in include/wavefront/scene_types.h, sampled and looked up by
// kernels/lights/environment.h): loaded from an equirectangular .exr or .hdr,
// or a constant radiance. The device scene (host/device/device_scene.h)
// uploads its header, texels and distribution.
//
// Texels: NaN or infinite values reject the file (InputError); negative ones
// (ringing from lossy EXR compression) are clamped to 0 with one warning. A
// map that is black everywhere keeps its (zero) radiance and samples the
// sphere by solid angle, with a warning. An image whose width is not twice
// its height is used as it is, with a warning.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"
#include "wavefront/scene_types.h"

namespace wf {

struct EnvironmentMap {
    Environment header{};
    std::vector<float> texels;       // 4 per texel: RGB radiance before scale, solid-angle pdf
    std::vector<float> distribution; // marginal CDF (height + 1), then per-row CDFs (width + 1 each)
    std::vector<std::string> warnings;
};

// `scale` multiplies the radiance; `rotate_degrees` turns the map about +y
// (world = R_y(rotate) map, see kernels/lights/environment.h).
// Throws InputError naming the file when it is missing, unreadable, not a
// float format, has fewer than three channels, or holds NaN/Inf texels.
EnvironmentMap load_environment(const std::string& path, float scale = 1.0f, float rotate_degrees = 0.0f);

// The same from an image in memory; `name` is what messages call it.
EnvironmentMap make_environment(const Image& image, float scale, float rotate_degrees,
                                const std::string& name);

// The same radiance from every direction, sampled uniformly over the sphere;
// radiance 1 is the furnace ("uniform white") for scenes without lights.
EnvironmentMap constant_environment(float radiance = 1.0f);

// A scene with no light at all (no emissive triangle, no punctual light, no
// environment), or whose only light is emission from textures, gets the
// uniform white environment of radiance 1 and a warning saying so, so that
// every asset renders something sensible.
void light_unlit_scene(Scene& scene);

} // namespace wf
