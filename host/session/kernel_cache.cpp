// kernel_cache.cpp — a scene is warmed lit as a render without --env would
// light it, so that the kernels compiled are those its render asks for.
#include "session/kernel_cache.h"

#include <filesystem>
#include <optional>
#include <ostream>

#include "base/errors.h"
#include "device/opencl_device.h"
#include "device/program_cache.h"
#include "gltf/gltf_loader.h"
#include "render/device_renderer.h"
#include "scene/environment_map.h"

namespace wf {

std::string cache_directory(const std::string& requested) {
    if (!requested.empty()) return requested;
    const std::optional<std::filesystem::path> fallback = ProgramCache::default_directory();
    return fallback ? fallback->string() : std::string();
}

void warm_cache(const CacheOptions& options, std::ostream& out) {
    const std::string directory = cache_directory(options.directory);
    if (directory.empty()) throw InputError("cache warm: no cache directory (set --cache-dir, XDG_CACHE_HOME or HOME)");
    const OpenClDevice device = open_device(options.device);
    RenderSettings settings;
    settings.cache_dir = directory;
    for (const std::string& path : options.scenes) {
        Scene scene = load_gltf(path);
        light_unlit_scene(scene);
        std::optional<Scene> flat;
        const Scene& rendered = scene_for_devices(scene, {&device}, settings, flat);
        std::string features;
        const KernelProgram program = build_render_program(device, rendered, settings, &features);
        out << path << ": " << features << ": " << (program.from_cache ? "already cached" : "compiled") << " in "
            << program.build_seconds << " s\n";
    }
    out << "cache: " << directory << "\n";
}

void clear_cache(const CacheOptions& options, std::ostream& out) {
    const std::string directory = cache_directory(options.directory);
    if (directory.empty()) throw InputError("cache clear: no cache directory (set --cache-dir, XDG_CACHE_HOME or HOME)");
    out << "removed " << ProgramCache(directory).clear() << " compiled programs from " << directory << "\n";
}

} // namespace wf
