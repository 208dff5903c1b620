// device_renderer.cpp — the order of set-up: everything that can be rejected
// (the device's memory) is rejected before any long work starts.
#include "render/device_renderer.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "base/errors.h"
#include "bvh/instance_bvh.h"
#include "scene/mesh_placement.h"
#include "device/layout_check.h"
#include "integrator/megakernel_integrator.h"
#include "integrator/path_pool.h"
#include "device/scene_features.h"
#include "integrator/wavefront_integrator.h"

namespace wf {
namespace {

std::string mib(size_t bytes) { return std::to_string((bytes + 1048575) / 1048576) + " MiB"; }

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

// The schedule asked for, or with Schedule::Auto the device's default.
Schedule schedule_for(const DeviceInfo& device, const RenderSettings& settings) {
    return settings.schedule == Schedule::Auto ? default_schedule(device.type, settings.sort_materials)
                                               : settings.schedule;
}

// How the kernels push, as asked, or with QueuePush::Auto the kind of
// kernels' own: a GPU's gathers a work-group's shares with local atomics, a
// CPU's with one work-item's loop, where a work-group runs on one thread and
// each local atomic is a locked instruction (kernels/common/queue_push.h).
QueuePush queue_push_for(const DeviceInfo& device, const RenderSettings& settings) {
    if (settings.queue_push != QueuePush::Auto) return settings.queue_push;
    return gpu_kernels(device, settings) ? QueuePush::Group : QueuePush::Serial;
}

// The group schedule's lanes: as asked, else 8 where the device's vectors hold
// 8 floats or more (AVX2, AVX-512), and 1 (no lanes) on devices of narrower
// vectors, GPUs among them, whose work-items are lanes already (so in a GPU's
// kernels wherever they run). Not 16 on AVX-512: on the Cornell box 16 lanes
// ran 0.88-0.90x the speed of 8, with 67% of them filled against 82%
// (bench/results/shading-lanes.md).
unsigned lane_width(const DeviceInfo& device, const RenderSettings& settings, bool gpu_kernels) {
    if (settings.lane_width != 0) return settings.lane_width;
    return device.native_float_width >= 8 && !gpu_kernels ? 8u : 1u;
}

// Rays a work-item traces at once (kernels/geometry/trace_width.h): as asked,
// else two on a CPU where the scene's triangle blocks alone are more than the
// device's cache holds. Two paid only there (bench/results/ray-throughput.md,
// 2026-12-04): MetalRoughSpheresNoTextures' 50 MB of blocks, bounce rays 1.15-1.2x;
// ToyCar's 5 MB, the same speed; the Cornell box's 1.5 KB, 0.9x.
uint32_t trace_width(const DeviceInfo& device, const Scene& scene, const RenderSettings& settings) {
    if (settings.trace_width != 0) return settings.trace_width;
    const unsigned long long blocks =
        (scene.triangle_count() + WF_BLOCK_LANES - 1) / WF_BLOCK_LANES * sizeof(TriangleBlock);
    return !gpu_kernels(device, settings) && device.global_cache > 0 && blocks > device.global_cache ? 2u : 1u;
}

// The settings with the schedule and the kind of kernels the device takes where they say Auto.
RenderSettings resolved_for(const DeviceInfo& device, const RenderSettings& settings) {
    RenderSettings resolved = settings;
    resolved.schedule = schedule_for(device, settings);
    resolved.queue_push = queue_push_for(device, settings);
    resolved.kernels = gpu_kernels(device, settings) ? KernelKind::Gpu : KernelKind::Cpu;
    return resolved;
}

} // namespace

bool gpu_kernels(const DeviceInfo& device, const RenderSettings& settings) {
    return settings.kernels == KernelKind::Auto ? device.type != "cpu" : settings.kernels == KernelKind::Gpu;
}

const Scene& scene_for_devices(const Scene& scene, const std::vector<const OpenClDevice*>& devices,
                               const RenderSettings& settings, std::optional<Scene>& flat) {
    if (scene.instances.empty()) return scene;
    for (const OpenClDevice* device : devices) {
        if (!gpu_kernels(device->info, settings)) continue;
        if (scene.placed_triangle_count() > size_t{WF_BVH_FIRST_MASK} + 1)
            throw InputError("the scene's " + std::to_string(scene.placed_triangle_count()) +
                             " placed triangles, written out for " + device->info.name +
                             "'s kernels (a GPU's traversal walks one tree), exceed the BVH's 2^28; "
                             "render with a CPU's kernels (--kernels cpu, or auto on a CPU device), which keep "
                             "its shared meshes once");
        return *(flat = flattened(scene));
    }
    return scene;
}

RenderProgramSource render_program_source(const DeviceInfo& device, const SceneFeatures& features,
                                          const RenderSettings& settings) {
    RenderProgramSource p;
    p.root = settings.integrator == Integrator::Megakernel ? "megakernel.cl" : "wavefront.cl";
    p.options = feature_defines(features);
    const bool gpu = gpu_kernels(device, settings);
    // Device functions a GPU's linker can always find (wavefront/compat.h); PoCL runs faster without.
    // The glass table out of the constant bank, which holds 64 KiB on NVIDIA's GPUs (bsdf/albedo.h), and
    // a traversal whose short stack lives in local memory, sized by the launch's local size
    // (geometry/bvh_traverse.h).
    if (gpu)
        p.options += " -DWF_STATIC_FUNCTIONS=1 -DWF_GLASS_TABLE_IN_SCENE=1 -DWF_GPU_TRAVERSAL=1 -DWF_TRAVERSAL_LOCAL_SIZE=" +
                     std::to_string(settings.local_size);
    if (settings.aovs & WF_AOV_FIRST_HIT) p.options += " -DWF_HAS_AOVS=1"; // absent, the first hit adds nothing beside radiance
    const QueuePush push = queue_push_for(device, settings);
    if (push != QueuePush::Group) // the kernels' own default needs no define
        p.options += " -DWF_QUEUE_PUSH=" + std::to_string(static_cast<int>(push));
    const bool group = settings.integrator == Integrator::Wavefront && schedule_for(device, settings) == Schedule::Group;
    // The scan, the serial sum and the group schedule size their local arrays by the launch's local size.
    if (push == QueuePush::Scan || push == QueuePush::Serial || group)
        p.options += " -DWF_LOCAL_SIZE=" + std::to_string(settings.local_size);
    if (group) p.options += " -DWF_GROUP_SCHEDULE=1"; // group_wavefront, left out of the other schedules' programs
    // The group schedule shades BSDF kinds in lanes as wide as the device's vectors (kernels/stages/shade_lanes.h).
    if (const unsigned lanes = lane_width(device, settings, gpu); group && lanes > 1)
        p.options += " -DWF_LANE_WIDTH=" + std::to_string(lanes);
    if (settings.trace_width > 1) p.options += " -DWF_TRACE_WIDTH=" + std::to_string(settings.trace_width);
    if (shade_in_two_kernels(resolved_for(device, settings))) p.options += " -DWF_SHADE_IN_TWO=1";
    return p;
}

KernelProgram build_render_program(const OpenClDevice& device, const Scene& scene, const RenderSettings& settings,
                                   std::string* features_described) {
    SceneFeatures features = settings.specialize ? scene_features(scene) : SceneFeatures::all();
    features.instances = !scene.instances.empty();
    RenderSettings resolved = settings;
    resolved.trace_width = trace_width(device.info, scene, settings);
    if (features_described)
        *features_described = describe_features(features) + (settings.specialize ? "" : " (--no-specialize)") +
                              (resolved.trace_width > 1 ? "; two rays a work-item" : "");
    const std::optional<ProgramCache> cache =
        settings.cache_dir.empty() ? std::nullopt : std::optional<ProgramCache>(ProgramCache(settings.cache_dir));
    const RenderProgramSource source = render_program_source(device.info, features, resolved);
    return build_kernel_program(device, source.root, source.options, cache ? &*cache : nullptr);
}

SceneBuild::SceneBuild(const Scene& scene) {
    const auto start = std::chrono::steady_clock::now();
    bvh = build_scene_bvh(scene);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    data = make_device_scene_data(scene, bvh);
}

DeviceRenderer::DeviceRenderer(const OpenClDevice& device, const Scene& scene, const SceneBuild& build,
                               const SceneCamera& camera, ImageSize size, const RenderSettings& requested)
    : device_(device) {
    RenderSettings settings = resolved_for(device.info, requested);
    const bool shade_records = shade_in_two_kernels(settings);
    // The one place the pool size is chosen: the request or the default,
    // capped at the pixels, and by default at what the device holds (below).
    const uint32_t default_pool =
        default_pool_size(device.info.type, device.info.compute_units, requested.integrator);
    settings.pool_size =
        choose_pool_size(requested.pool_size, default_pool, size.width * size.height, &summary_.pool_note);
    const DeviceSceneData& data = build.data;
    const Bvh& bvh = build.bvh;
    summary_.times.bvh_build = build.seconds;

    const size_t pixels = size_t{size.width} * size.height;
    const size_t film_bytes = Film::bytes_for(size.width, size.height, settings.bounce_layers, settings.aovs);
    if (requested.pool_size == 0) {
        // The default pool, capped to half the memory the scene and the film
        // leave, and to the largest buffer the device allocates: a small
        // device renders with fewer paths in flight rather than failing.
        const uint32_t fits = pool_that_fits(settings.pool_size, device.info.global_memory,
                                             device.info.max_allocation, data.bytes() + film_bytes, shade_records);
        if (fits > 0 && fits < settings.pool_size) {
            settings.pool_size = fits;
            summary_.pool_note = "pool of " + std::to_string(fits) + " paths, what " + device.info.name +
                                 "'s memory holds beside the scene and the image (" +
                                 mib(device.info.global_memory) + ")";
        }
    }
    check_device_memory(device.info, data.bytes(), size_t{settings.pool_size} * PathPool::bytes_per_path(shade_records),
                        film_bytes, std::max({data.largest_buffer_bytes(), pixels * settings.bounce_layers * sizeof(cl_float4),
                                  pixels * sizeof(cl_float4),
                                  size_t{settings.pool_size} * PathPool::largest_bytes_per_path(shade_records)}));

    const std::string probe_warning = check_shared_layouts(device);
    program_ = build_render_program(device, scene, settings, &summary_.features);
    summary_.build_warning = probe_warning.empty() ? program_.warning : probe_warning;
    summary_.kernels_from_cache = program_.from_cache;
    device_scene_ = upload_scene(device.context, data);
    const Camera device_camera = make_device_camera(camera, size);
    if (settings.integrator == Integrator::Megakernel)
        integrator_ = std::make_unique<MegakernelIntegrator>(device, program_.program, device_scene_, device_camera,
                                                             settings);
    else
        integrator_ = std::make_unique<WavefrontIntegrator>(device, program_.program, device_scene_, device_camera,
                                                            settings);

    summary_.device = device.info.name + " (" + device.info.type + ", " + std::to_string(device.info.compute_units) +
                      " compute units, " + device.info.platform + ")";
    summary_.times.kernel_build = program_.build_seconds;
    summary_.triangles = scene.triangle_count();
    summary_.placed_triangles = scene.placed_triangle_count();
    summary_.materials = scene.materials.size();
    summary_.emissive_triangles = data.emissive_triangles;
    summary_.punctual_lights = data.punctual.size();
    summary_.environment = scene.environment != nullptr;
    summary_.bvh_nodes = bvh.nodes.size();
    summary_.bvh_depth = bvh.depth;
    summary_.queue_push = settings.queue_push;
    summary_.local_size = settings.local_size;
    summary_.traversal_bytes = data.traversal_bytes();
    summary_.width = size.width;
    summary_.height = size.height;
    summary_.device_bytes = device_scene_.bytes + integrator_->stats().pool_bytes + integrator_->film().bytes();
}

bool DeviceRenderer::resume(const FilmState& state) {
    // Slot i takes its pixels i, i + pool, ... in turn, so a render this pool
    // stopped leaves each slot's first pixels one sample ahead of the rest,
    // never a pixel behind one that comes after it; the count of samples it
    // started is their sum.
    const uint32_t pool = integrator_->pool().size();
    std::vector<uint32_t> started(pool, 0u);
    for (size_t p = 0; p < state.samples.size(); ++p) {
        const uint32_t slot = static_cast<uint32_t>(p % pool);
        const uint32_t n = state.samples[p], first = state.samples[slot];
        const uint32_t previous = p >= pool ? state.samples[p - pool] : n;
        if (n > previous || n + 1 < first) return false;
        started[slot] += n;
    }
    integrator_->restore(state, started);
    return true;
}

void DeviceRenderer::render_unit(uint32_t first, uint32_t count, uint32_t round_spp, FilmState& image, bool held) {
    const Film& film = integrator_->film();
    auto start = std::chrono::steady_clock::now();
    auto timed = [&] {
        const auto now = std::chrono::steady_clock::now();
        transfer_seconds_ += std::chrono::duration<double>(now - start).count();
    };
    if (!held) film.write_pixels(device_.queue, first, count, image);
    integrator_->trace_pixels(first, std::vector<uint32_t>(image.samples.begin() + first,
                                                           image.samples.begin() + first + count));
    timed();
    integrator_->render_to(round_spp);
    start = std::chrono::steady_clock::now();
    film.read_pixels(device_.queue, first, count, image);
    timed();
}

RenderSummary DeviceRenderer::summary() const {
    RenderSummary s = summary_;
    s.stats = stats();
    s.spp = static_cast<uint32_t>(s.stats.samples / (size_t{s.width} * s.height));
    return s;
}

} // namespace wf
