// camera.cpp — pinhole camera set-up. The image's own aspect always wins over a
// file's aspectRatio, keeping the vertical field of view, as glTF viewers do.
#include "scene/camera.h"

#include <cmath>

#include "base/errors.h"

namespace wf {

ImageSize resolve_image_size(uint32_t width, uint32_t height, const std::optional<SceneCamera>& camera) {
    const float aspect = camera && camera->aspect > 0.0f ? camera->aspect : 1.0f;
    if (width == 0 && height == 0) width = kDefaultImageWidth;
    if (width == 0) width = std::max(1u, static_cast<uint32_t>(std::lround(height * aspect)));
    if (height == 0) height = std::max(1u, static_cast<uint32_t>(std::lround(width / aspect)));
    return {width, height};
}

SceneCamera frame_bounds(const Bounds& bounds) {
    SceneCamera c;
    const float radius = 0.5f * glm::length(bounds.extent());
    const float distance = radius / std::sin(0.5f * c.vertical_fov);
    c.position = bounds.center() + glm::vec3(0.0f, 0.0f, distance);
    c.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    c.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return c;
}

SceneCamera camera_looking_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float vertical_fov) {
    const glm::vec3 view = target - eye;
    const float length = glm::length(view);
    if (!(length > 0.0f) || !std::isfinite(length)) throw InputError("render: --look-at: the eye is the target");
    SceneCamera c;
    c.position = eye;
    c.forward = view / length;
    const glm::vec3 right = glm::cross(c.forward, up);
    if (!(glm::length(right) > 1e-6f * glm::length(up)))
        throw InputError("render: --look-at: the up direction lies along the view");
    c.up = glm::normalize(glm::cross(glm::normalize(right), c.forward));
    c.vertical_fov = vertical_fov;
    return c;
}

Camera make_device_camera(const SceneCamera& camera, ImageSize size) {
    Camera d{};
    const glm::vec3 forward = glm::normalize(camera.forward);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    for (int i = 0; i < 3; ++i) {
        d.origin[i] = camera.position[i];
        d.forward[i] = forward[i];
        d.right[i] = right[i];
        d.up[i] = up[i];
    }
    d.tan_half_fov_y = std::tan(0.5f * camera.vertical_fov);
    d.aspect = static_cast<float>(size.width) / static_cast<float>(size.height);
    d.width = size.width;
    d.height = size.height;
    return d;
}

} // namespace wf
