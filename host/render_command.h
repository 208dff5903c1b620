// render_command.h — `wavefront render`: load, build, render, write, report.
#pragma once

#include <iosfwd>

#include "camera.h"
#include "cli.h"
#include "film.h"
#include "opencl_device.h"
#include "render_report.h"
#include "scene.h"

namespace wf {

struct RenderOutput {
    Image image;
    RenderSummary summary;
};

// Everything after loading: the BVH, the memory check, the kernels, the
// wavefront loop. Used by run_render and by the tests, so both take one path.
RenderOutput render_scene(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera,
                          ImageSize size, const RenderSettings& settings);

// Runs one render as the options say, writes the image and returns the
// summary. Progress and the report go to `log`.
RenderSummary run_render(const RenderOptions& options, std::ostream& log);

// `wavefront devices`: one line per OpenCL device.
void print_devices(std::ostream& out);

} // namespace wf
