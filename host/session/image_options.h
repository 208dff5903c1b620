// image_options.h — what shapes a render's image, as name and value pairs:
// written into every output's metadata, and checked by --resume, which goes
// on from a partial render only under the same values. The pool and the
// devices are not among them: they change no byte (renderer.h).
#pragma once

#include <string>

#include "image/image_io.h"
#include "scene/camera.h"
#include "session/render_options.h"

namespace wf {

// The options of the image `o` asks for at `size`.
ImageOptions image_options(const RenderOptions& o, ImageSize size);

// The options of an image that --denoise made: those of the render, and the denoiser.
ImageOptions with_denoiser(ImageOptions options);

// What a partial render must share with this one to go on: every option but
// the scene's path, since the scene's contents decide wherever it now lies.
ImageOptions resume_checks(ImageOptions options);

// The scene's absolute path without links or dot segments, for metadata.
std::string canonical_path(const std::string& path);

// --aov's value for these settings ("albedo,bounces"), or "none".
std::string aov_names(const RenderSettings& settings);

} // namespace wf
