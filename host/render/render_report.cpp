// render_report.cpp — ray rates are given twice: over the render's wall time
// (what a user waits for) and over the intersect kernels' own time (what the
// traversal achieves), so a slow scheduler cannot hide behind a fast kernel.
#include "render/render_report.h"

#include <iomanip>
#include <ostream>

#include "integrator/path_pool.h"

namespace wf {
namespace {

double per_second(double count, double seconds) { return seconds > 0.0 ? count / seconds : 0.0; }

} // namespace

void print_report(std::ostream& out, const RenderSummary& s) {
    const RenderStats& st = s.stats;
    const double kernel = st.kernel_seconds();
    const double closest_kernel = st.stages[STAGE_INTERSECT].seconds;
    const double shadow_kernel = st.stages[STAGE_INTERSECT_SHADOW].seconds;
    out << std::fixed << std::setprecision(3);
    out << "scene      " << s.scene << ": " << s.triangles << " triangles, ";
    if (s.placed_triangles != s.triangles) out << s.placed_triangles << " as placed, ";
    out << s.materials << " materials, "
        << s.emissive_triangles << " emissive triangles, " << s.punctual_lights << " punctual lights, "
        << (s.environment ? "an environment" : "no environment") << "\n";
    out << "features   " << s.features << "\n";
    out << "device     " << s.device;
    if (s.ranks > 1) out << " on " << s.ranks << " MPI ranks";
    out << "\n";
    for (size_t d = 0; d < s.shares.size(); ++d) {
        const DeviceShare& share = s.shares[d];
        out << std::setprecision(1) << "  [" << d << "]      " << share.device << ": "
            << 100.0 * per_second(share.samples, st.samples) << "% of the samples in " << share.units
            << " units, " << std::setprecision(2) << per_second(share.samples, share.busy_seconds) * 1e-6
            << " M samples/s busy, " << std::setprecision(3) << share.transfer_seconds << " s moving sums\n";
    }
    out << "image      " << s.width << " x " << s.height << ", " << s.spp;
    if (s.most_spp > s.spp)
        out << " to " << s.most_spp << " spp, " << std::setprecision(1) << s.mean_spp << " on average"
            << std::setprecision(3);
    else
        out << " spp";
    if (s.resumed_from_spp) out << " (resumed from " << s.resumed_from_spp << ")";
    out << (s.output.empty() ? "" : " -> " + s.output) << "\n"; // none where no file was written (Python)
    out << "times      load " << s.times.load << " s, BVH build " << s.times.bvh_build << " s (" << s.bvh_nodes
        << " nodes, depth " << s.bvh_depth << "), kernel build " << s.times.kernel_build << " s"
        << (s.kernels_from_cache ? " (from cache)" : "") << ", render "
        << st.seconds << " s";
    if (s.times.denoise > 0.0) out << ", denoise " << s.times.denoise << " s";
    out << "\n";
    out << std::setprecision(2);
    out << "samples    " << st.samples << " at " << per_second(st.samples, st.seconds) * 1e-6 << " M/s; mean path "
        << per_second(st.closest_rays, st.samples) << " segments; non-finite samples " << st.nonfinite_samples << "\n";
    if (st.lane_slots > 0) // the group schedule's BSDF lanes (kernels/stages/shade_lanes.h)
        out << "lanes      " << st.lane_paths << " BSDF queries in lanes, " << std::setprecision(1)
            << 100.0 * per_second(st.lane_paths, st.lane_slots) << "% of the lanes filled\n"
            << std::setprecision(2);
    // Rays a second inside the intersect kernels, where there are such kernels
    // (a kernel that runs whole paths has no intersect time of its own).
    out << "rays       closest " << st.closest_rays << " (" << per_second(st.closest_rays, st.seconds) * 1e-6
        << " M/s wall";
    if (closest_kernel > 0.0) out << ", " << per_second(st.closest_rays, closest_kernel) * 1e-6 << " M/s in intersect";
    out << "), shadow " << st.shadow_rays << " (" << per_second(st.shadow_rays, st.seconds) * 1e-6 << " M/s wall";
    if (shadow_kernel > 0.0)
        out << ", " << per_second(st.shadow_rays, shadow_kernel) * 1e-6 << " M/s in intersect_shadow";
    out << ")\n";
    out << "memory     " << std::setprecision(1) << s.device_bytes / 1048576.0 << " MiB on the device; pool "
        << st.pool_size << " paths of " << PathPool::state_bytes_per_path() << " bytes, queues "
        << PathPool::queue_bytes_per_path() << " bytes a path";
    if (st.shade_record_bytes) out << ", shade records " << st.shade_record_bytes << " bytes a path";
    out << "; BVH and triangles " << per_second(s.traversal_bytes, s.triangles) << " bytes a triangle\n";
    const bool megakernel = st.integrator == Integrator::Megakernel;
    out << "schedule   " << integrator_name(st.integrator);
    if (megakernel) out << ": " << st.iterations << " launches";
    else out << ", " << schedule_name(st.schedule) << ": " << st.iterations << " iterations";
    // Several devices work at once: their kernel time is set against the time each was busy.
    double busy = s.shares.empty() ? st.seconds : 0.0;
    for (const DeviceShare& d : s.shares) busy += d.busy_seconds;
    out << ", pool occupancy " << std::setprecision(1) << 100.0 * st.pool_occupancy() << "%; kernels "
        << std::setprecision(3) << kernel << " s, host and transfers " << busy - kernel << " s ("
        << std::setprecision(1) << 100.0 * per_second(busy - kernel, busy) << "%)"
        << (s.shares.empty() ? "" : ", over every device") << "\n";
    out << "path lengths";
    for (int b = 0; b < WF_PATH_LENGTH_BUCKETS; ++b) {
        if (!st.path_lengths[b]) continue;
        const uint64_t lo = b == 0 ? 0 : uint64_t{1} << (b - 1), hi = (uint64_t{1} << b) - 1;
        out << "  " << lo;
        if (b == WF_PATH_LENGTH_BUCKETS - 1) out << "+";
        else if (hi > lo) out << "-" << hi;
        out << ": " << std::setprecision(1) << 100.0 * per_second(st.path_lengths[b], st.samples) << "%";
    }
    out << " (bounces per sample)\n";
    out << "stage              launches     seconds   share\n";
    for (int stage = 0; stage < STAGE_COUNT; ++stage) {
        // Where one kernel runs every stage (the megakernel, the group schedule), its row alone.
        const Stage single = st.whole_path_stage();
        if (single != STAGE_COUNT ? stage != single : stage == STAGE_MEGAKERNEL || stage == STAGE_GROUP) continue;
        const StageTime& t = st.stages[stage];
        out << "  " << std::left << std::setw(18) << t.name << std::right;
        if (t.launches == 0 && st.iterations > 0) { // a stage the scene cannot use
            out << "  left out\n";
            continue;
        }
        out << std::setw(8) << t.launches << std::setw(12) << std::setprecision(3) << t.seconds << std::setw(7)
            << std::setprecision(1) << 100.0 * per_second(t.seconds, kernel) << "%\n";
    }
}

} // namespace wf
