// cli.h — the command line: `wavefront render SCENE [flags]`, `wavefront
// devices`, `wavefront cache warm|clear`, `--help` on each, `--version`. Every
// flag value is checked here; a bad one is an InputError that names the
// command, the flag and the value.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "integrator/render_settings.h"
#include "render/progress_options.h"

namespace wf {

struct RenderOptions {
    std::string scene;
    std::string output = "render.png";
    uint32_t width = 0;  // 0: from the camera's aspect
    uint32_t height = 0;
    int camera = -1;     // -1: the file's first perspective camera
    std::optional<std::array<float, 9>> look_at; // eye, target, up: a camera of the command line's instead
    std::optional<float> fov;                    // vertical, degrees: the camera's own when not given
    std::string device;  // empty: the first GPU, else the first device
    std::string cache_dir;          // --cache-dir; empty: the default (program_cache.h)
    std::string environment;        // an equirectangular map; empty: none
    float environment_rotate = 0.0f; // degrees about +y
    float environment_scale = 1.0f;
    std::optional<float> environment_uniform; // a constant environment of this radiance instead; 0: none at all
    RenderSettings settings;
    ProgressOptions progress; // its max_spp is settings.spp, or 0 when only time or error bounds the render
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

// `wavefront cache warm|clear`.
struct CacheOptions {
    std::string directory;           // --cache-dir, else the default (program_cache.h)
    std::string device;              // for warm
    std::vector<std::string> scenes; // for warm
};

enum class Command { Render, Devices, Help, Version, CacheWarm, CacheClear };

struct CommandLine {
    Command command = Command::Help;
    RenderOptions render;
    CacheOptions cache;
    std::string help; // the text to print for Command::Help
};

CommandLine parse_command_line(int argc, const char** argv);

// A flag of `wavefront render` as the command line declares it, for front ends
// that must offer the same flags (the Python module's keywords).
struct FlagInfo {
    std::string name;        // "pool-size"
    std::string type;        // its kind and check, as --help shows them: "UINT:in 1 to 67108864", "FILE"
    std::string help;        // one line, ending "(default: ...)"
    bool takes_value = true; // false: a flag alone (--quiet)
};
std::vector<FlagInfo> render_flags();

// --aov's value for these settings ("albedo,bounces"), or "none".
std::string aov_names(const RenderSettings& settings);

} // namespace wf
