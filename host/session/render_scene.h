// render_scene.h — the scene a render request names, made ready to render:
// loaded with its camera, lit by the environment the options give (or by a
// white one when it has no light at all), and seen through --look-at's or
// --fov's camera. Every rank of an MPI render loads it the same way.
#pragma once

#include <iosfwd>

#include "scene/scene.h"
#include "session/render_options.h"

namespace wf {

// The scene the options name, with its environment and a light if it has
// none (light_for_render): what every rank of a render loads. Warnings go to `log`.
Scene load_render_scene(const RenderOptions& options, std::ostream& log);
void light_for_render(Scene& scene, const RenderOptions& options, std::ostream& log);

// --look-at's camera in place of the file's, and --fov on whichever camera renders.
void camera_for_render(Scene& scene, const RenderOptions& options);

} // namespace wf
