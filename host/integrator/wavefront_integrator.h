// wavefront_integrator.h — the host loop that drives the stage kernels over
// the path pool until every pixel has its samples.
//
//   generate → intersect → shade → intersect_shadow → roulette → accumulate
//
// Each stage reads one queue of path slots and appends to others (shade in
// two kernels, surface then shade, where shade_in_two_kernels); a slot is
// in one queue at a time, so any order of launches is correct and the
// schedule (--schedule) changes the speed, never the image:
//   refill  — one iteration launches every stage once, in pipeline order,
//             each at its queue's length; slots freed by accumulate are
//             refilled by generate at the start of the next, so the pool
//             stays full until the last samples of a round are started;
//   passes  — pbrt-v4's way: the same iterations, but new samples start only
//             once every path of the pass has ended, so each iteration is one
//             depth and the pool drains at the end of every pass;
//   fullest — Cycles X's way: read the queue counters after every launch and
//             launch the stage whose queue is longest;
//   group   — one kernel (group_wavefront) in which each work-group runs the
//             stages over its own slots and local queues, one launch per
//             sample of every slot, as the megakernel's: the working set of a
//             stage stays in the core's caches.
// --sort-materials adds a counting sort of the extension queue by material
// between intersect and shade (kernels/stages/sort_by_material.h).
#pragma once

#include <array>

#include "integrator/path_integrator.h"

namespace wf {

class WavefrontIntegrator : public PathIntegrator {
public:
    WavefrontIntegrator(const OpenClDevice& device, const cl::Program& program, const DeviceScene& scene,
                        const Camera& camera, const RenderSettings& settings);

    void render_to(uint32_t round_spp) override;

private:
    void set_stage_args();
    void launch(Stage stage, uint32_t items) { PathIntegrator::launch(stage, kernels_[stage], items); }
    void run_iterations(bool passes);
    void run_fullest_first();
    // The stages that take the extension queue (intersect, shade) over
    // `items` paths of it, sorted by material before shade when the settings ask.
    void extend(uint32_t items);
    void sort_by_material(uint32_t items);
    // The first of the queues that the stages after shade take, refill's
    // second phase: those before it are generate's and the extension queue.
    static constexpr int kLaterQueue = WF_QUEUE_SHADOW;
    // The stage of the list that takes `queue` first.
    static Stage consumer_of(QueueId queue);

    std::array<cl::Kernel, kStageKernels> kernels_; // one per stage of the stage list, by name
    // --sort-materials only: its kernels, the key counts and the sorted queue.
    cl::Kernel count_materials_, scan_materials_, scatter_materials_;
    cl::Kernel group_;   // --schedule group only
    cl::Kernel surface_; // shade's first kernel, where shade_in_two_kernels (path_integrator.h)
    cl::Buffer key_counts_, sorted_;
};

} // namespace wf
