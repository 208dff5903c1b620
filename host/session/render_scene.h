// render_scene.h — the scene a render request names, made ready to render:
// loaded with its camera, lit by the environment the options give (or by a
// white one when it has no light at all), and seen through --look-at's or
// --fov's camera. Every rank of an MPI render loads it the same way.
#pragma once

#include <iosfwd>

#include "scene/scene.h"
#include "session/render_options.h"

namespace wf {

// The scene the options name, made ready (ready_for_render): what every rank
// of a render loads. Warnings go to `log`.
Scene load_render_scene(const RenderOptions& options, std::ostream& log);
// A loaded scene lit by the options' environment, and by a white one where it
// has no light at all; then --look-at's camera in place of the file's, and
// --fov on whichever camera renders.
void ready_for_render(Scene& scene, const RenderOptions& options, std::ostream& log);

} // namespace wf
