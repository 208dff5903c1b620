// render_report.h — the closing report of a render: what it cost, stage by
// stage, and whether any sample went non-finite.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "integrator/path_integrator.h"

namespace wf {

struct RenderTimes {
    double load = 0.0;
    double bvh_build = 0.0;
    double kernel_build = 0.0;
    double denoise = 0.0; // --denoise: Open Image Denoise's filters (image/denoiser.h)
};

// One device's part in a render over several (render/renderer.h).
struct DeviceShare {
    std::string device;
    uint64_t samples = 0;
    uint64_t units = 0;            // runs of pixels it traced
    double busy_seconds = 0.0;     // in its units, transfers included
    double transfer_seconds = 0.0; // moving its units' sums to and from the host's image
};

struct RenderSummary {
    std::string scene;
    size_t triangles = 0;        // held: a shared mesh's once
    size_t placed_triangles = 0; // as placed: a shared mesh's once per instance
    size_t materials = 0;
    size_t emissive_triangles = 0;
    size_t punctual_lights = 0;
    bool environment = false;
    std::string features; // what the kernels were compiled for
    bool kernels_from_cache = false;
    size_t bvh_nodes = 0;
    int bvh_depth = 0;
    std::string device;
    uint32_t width = 0, height = 0, spp = 0; // spp: the fewest a pixel has
    uint32_t most_spp = 0;  // the most a pixel has: more than spp where --adaptive stopped pixels apart
    double mean_spp = 0.0;
    uint32_t resumed_from_spp = 0; // the samples per pixel of the partial render it went on from; 0: none
    size_t device_bytes = 0;
    QueuePush queue_push = QueuePush::Group;
    uint32_t local_size = 0;
    size_t traversal_bytes = 0; // the BVH nodes and the triangles they hold: what intersection reads
    RenderTimes times;
    RenderStats stats;
    std::string output;
    int interrupted_by = 0; // the signal that stopped the render early, or 0
    std::string pool_note;  // why the pool is not what was asked for (or the default), when it is not
    std::string build_warning; // a kernel build that failed once and was retried (kernel_program.h), when one was
    std::vector<DeviceShare> shares; // each device's part, when several took part
    int ranks = 1;                   // MPI ranks the devices were on
};

void print_report(std::ostream& out, const RenderSummary& s);

} // namespace wf
