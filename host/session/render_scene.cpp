// render_scene.cpp — a uniform environment of 0 is a black world, as asked,
// whatever lights the scene has; any other leaves an unlit scene lit.
#include "session/render_scene.h"

#include <memory>
#include <ostream>

#include "gltf/gltf_loader.h"
#include "scene/camera.h"
#include "scene/environment_map.h"

namespace wf {

namespace {

void light_for_render(Scene& scene, const RenderOptions& options, std::ostream& log) {
    if (!options.environment.empty()) {
        auto map = std::make_shared<EnvironmentMap>(
            load_environment(options.environment, options.environment_scale, options.environment_rotate));
        for (const std::string& w : map->warnings) log << "warning: " << w << "\n"; // each names the file
        scene.environment = std::move(map);
    }
    if (options.environment_uniform == 0.0f) return; // a black world, as asked, whatever lights the scene has
    if (options.environment_uniform)
        scene.environment = std::make_shared<EnvironmentMap>(constant_environment(*options.environment_uniform));
    light_unlit_scene(scene);
}

void camera_for_render(Scene& scene, const RenderOptions& o) {
    if (o.look_at) {
        const std::array<float, 9>& v = *o.look_at;
        scene.camera =
            camera_looking_at({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}, kDefaultVerticalFov);
    }
    if (o.fov) {
        if (!scene.camera) scene.camera = frame_bounds(scene.bounds());
        scene.camera->vertical_fov = glm::radians(*o.fov);
    }
}

} // namespace

void ready_for_render(Scene& scene, const RenderOptions& options, std::ostream& log) {
    light_for_render(scene, options, log);
    camera_for_render(scene, options);
}

Scene load_render_scene(const RenderOptions& options, std::ostream& log) {
    Scene scene = load_gltf(options.scene, LoadOptions{options.camera, options.instancing});
    ready_for_render(scene, options, log);
    return scene;
}

} // namespace wf
