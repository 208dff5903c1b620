// camera.h — the device camera for a render: the file's camera, or one that
// frames the scene's bounds when the file has none; and the image size that
// keeps the camera's aspect when the user gives only one side (or neither).
#pragma once

#include <cstdint>
#include <optional>

#include "scene/scene.h"
#include "wavefront/scene_types.h"

namespace wf {

struct ImageSize {
    uint32_t width = 0;
    uint32_t height = 0;
};

// 0 means "not given". The default width is 512.
// The width when neither side is asked for.
constexpr uint32_t kDefaultImageWidth = 512;

ImageSize resolve_image_size(uint32_t width, uint32_t height, const std::optional<SceneCamera>& camera);

// A camera looking down −z at the bounds, far enough back to see all of them.
SceneCamera frame_bounds(const Bounds& bounds);

// A camera at `eye` looking at `target`, `up` turned upright for it. Throws
// InputError when eye and target are one point or up lies along the view.
SceneCamera camera_looking_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float vertical_fov);

Camera make_device_camera(const SceneCamera& camera, ImageSize size);

} // namespace wf
