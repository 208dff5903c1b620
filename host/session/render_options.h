// render_options.h — the render request: everything a render is asked to do,
// whoever asks. `wavefront render`'s flags fill it (cli/cli.cpp), so do
// render()'s keywords in Python (through the same parser), and every MPI rank
// gets the same copy; run_render() (run_render.h) carries it out. No OpenCL.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "gltf/gltf_loader.h"
#include "integrator/render_settings.h"
#include "render/progress_options.h"

namespace wf {

struct RenderOptions {
    std::string scene;
    std::string output = "render.png";
    uint32_t width = 0;  // 0: from the camera's aspect
    uint32_t height = 0;
    int camera = -1;     // -1: the file's first perspective camera
    Instancing instancing = Instancing::Large; // which meshes several nodes place are kept once (gltf_loader.h)
    std::optional<std::array<float, 9>> look_at; // eye, target, up: a camera of the command line's instead
    std::optional<float> fov;                    // vertical, degrees: the camera's own when not given
    std::string device;  // empty: the first GPU, else the first device
    std::string cache_dir;          // --cache-dir; empty: the default (program_cache.h)
    std::string environment;        // an equirectangular map; empty: none
    float environment_rotate = 0.0f; // degrees about +y
    float environment_scale = 1.0f;
    std::optional<float> environment_uniform; // a constant environment of this radiance instead; 0: none at all
    RenderSettings settings;   // its spp 0 when only time or error bounds the render (cli.cpp)
    ProgressOptions progress;
    std::string reference;    // an image to report the error against
    std::string report_csv;   // where to write the checkpoints as CSV
    std::string stats_json;   // where to write the render's statistics (render_stats_json.h)
    double checkpoint_every = 0.0; // seconds between partial renders written to OUT.partial.exr; 0: none
    std::string resume;            // a partial render to go on from
    float exposure = 0.0f;         // 8-bit outputs: scaled by 2^exposure before the sRGB curve
    bool half = false;             // float outputs: 16-bit half channels
    bool quiet = false;            // errors only: no progress line, table, report, warning or note
    bool denoise = false;          // the image denoised by Open Image Denoise (image/denoiser.h); its albedo
                                   // and normal AOVs are on, settings.aovs holding them
    uint32_t aovs_asked = 0;       // the WF_AOV_* bits --aov named, beside those --denoise turns on
    int ranks = 1;                 // MPI ranks sharing the render: set by cluster_render.cpp, not a flag
};

} // namespace wf
