// render_command.cpp — the order of a render and the checks between its
// steps: everything that can be rejected (the scene, the flags, the device's
// memory) is rejected before any long work starts.
#include "render_command.h"

#include <chrono>
#include <iomanip>
#include <ostream>

#include "bvh_builder.h"
#include "camera.h"
#include "device_scene.h"
#include "errors.h"
#include "gltf_loader.h"
#include "image_writer.h"
#include "kernel_program.h"
#include "layout_check.h"
#include "opencl_device.h"
#include "path_pool.h"

namespace wf {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string mib(size_t bytes) { return std::to_string((bytes + 1048575) / 1048576) + " MiB"; }

// The render's buffers must fit the device before anything is allocated.
void check_device_memory(const DeviceInfo& device, size_t scene_bytes, size_t pool_bytes, size_t film_bytes,
                         size_t largest_buffer) {
    const size_t needed = scene_bytes + pool_bytes + film_bytes;
    if (needed > device.global_memory)
        throw InputError("the render needs " + mib(needed) + " of device memory (scene " + mib(scene_bytes) +
                         ", paths " + mib(pool_bytes) + ", image " + mib(film_bytes) + ") but " + device.name +
                         " has " + mib(device.global_memory));
    if (largest_buffer > device.max_allocation)
        throw InputError("the render needs a " + mib(largest_buffer) + " buffer but " + device.name +
                         " allocates at most " + mib(device.max_allocation) + " at once");
}

} // namespace

void print_devices(std::ostream& out) {
    for (const DeviceInfo& d : list_devices())
        out << "[" << d.index << "] " << d.name << "\n    type " << d.type << ", " << d.compute_units
            << " compute units, " << mib(d.global_memory) << " global memory (" << mib(d.max_allocation)
            << " per buffer)\n    platform " << d.platform << ", " << d.version << ", driver " << d.driver << "\n";
}

RenderOutput render_scene(const OpenClDevice& device, const Scene& scene, const SceneCamera& scene_camera,
                          ImageSize size, const RenderSettings& requested) {
    RenderOutput out;
    RenderSummary& summary = out.summary;
    summary.device = device.info.name + " (" + device.info.type + ", " + std::to_string(device.info.compute_units) +
                     " compute units, " + device.info.platform + ")";
    RenderSettings settings = requested;
    settings.pool_size = choose_pool_size(requested.pool_size, size.width * size.height, nullptr);

    auto start = std::chrono::steady_clock::now();
    const Bvh bvh = build_bvh(scene.positions);
    summary.times.bvh_build = seconds_since(start);
    const DeviceSceneData data = make_device_scene_data(scene, bvh);

    const size_t pool_bytes = size_t{settings.pool_size} * PathPool::bytes_per_path();
    const size_t film_bytes = Film::bytes_for(size.width, size.height);
    check_device_memory(device.info, data.bytes(), pool_bytes, film_bytes,
                        std::max({data.largest_buffer_bytes(), size_t{size.width} * size.height * sizeof(cl_float4),
                                  size_t{settings.pool_size} * WF_QUEUE_COUNT * sizeof(cl_uint)}));

    check_shared_layouts(device);
    const KernelProgram program = build_kernel_program(device, "wavefront.cl");
    summary.times.kernel_build = program.build_seconds;

    const DeviceScene device_scene = upload_scene(device.context, data);
    WavefrontScheduler scheduler(device, program.program, device_scene,
                                 make_device_camera(scene_camera, size), settings);
    summary.stats = scheduler.render();
    out.image = scheduler.film().resolve(device.queue);

    summary.triangles = scene.triangle_count();
    summary.materials = scene.materials.size();
    summary.emissive_triangles = data.lights.size();
    summary.bvh_nodes = bvh.nodes.size();
    summary.bvh_depth = bvh.depth;
    summary.width = size.width;
    summary.height = size.height;
    summary.spp = settings.spp;
    summary.device_bytes = device_scene.bytes + summary.stats.pool_bytes + scheduler.film().bytes();
    return out;
}

RenderSummary run_render(const RenderOptions& options, std::ostream& log) {
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = load_gltf(options.scene, LoadOptions{options.camera});
    const double load_seconds = seconds_since(start);
    for (const std::string& w : scene.warnings) log << "warning: " << options.scene << ": " << w << "\n";
    if (!scene.camera) log << "note: " << options.scene << " has no camera; framing its bounds\n";
    std::string pool_note;
    const ImageSize size = resolve_image_size(options.width, options.height, scene.camera);
    choose_pool_size(options.settings.pool_size, size.width * size.height, &pool_note);
    if (!pool_note.empty()) log << "note: " << pool_note << "\n";

    const OpenClDevice device = open_device(options.device);
    RenderOutput out = render_scene(device, scene, scene.camera ? *scene.camera : frame_bounds(scene.bounds()),
                                    size, options.settings);
    ImageMetadata metadata;
    metadata.samples_per_pixel = out.summary.spp;
    metadata.render_seconds = out.summary.stats.seconds;
    metadata.device = device.info.name;
    metadata.seed = options.settings.seed;
    metadata.scene = options.scene;
    write_image(options.output, out.image, metadata);

    out.summary.scene = options.scene;
    out.summary.output = options.output;
    out.summary.times.load = load_seconds;
    return out.summary;
}

} // namespace wf
