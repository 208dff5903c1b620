// render_stats_json.cpp — field names follow the closing report's words.
#include "render/render_stats_json.h"

#include <nlohmann/json.hpp>

#include "base/output_files.h"
#include "integrator/path_pool.h"

namespace wf {

void write_stats_json(const std::string& path, const RenderSummary& s) {
    const RenderStats& st = s.stats;
    nlohmann::json j;
    j["scene"] = s.scene;
    j["device"] = s.device;
    nlohmann::json shares = nlohmann::json::array();
    for (const DeviceShare& d : s.shares)
        shares.push_back({{"device", d.device},
                          {"samples", d.samples},
                          {"units", d.units},
                          {"busy_seconds", d.busy_seconds},
                          {"transfer_seconds", d.transfer_seconds}});
    j["device_shares"] = shares; // empty with one device
    j["ranks"] = s.ranks;
    j["features"] = s.features;
    j["triangles"] = s.triangles;
    j["placed_triangles"] = s.placed_triangles;
    j["width"] = s.width;
    j["height"] = s.height;
    j["spp"] = s.spp;
    j["most_spp"] = s.most_spp;
    j["mean_spp"] = s.mean_spp;
    j["resumed_from_spp"] = s.resumed_from_spp;
    j["integrator"] = integrator_name(st.integrator);
    j["schedule"] = st.integrator == Integrator::Megakernel ? "none" : schedule_name(st.schedule);
    j["pool_size"] = st.pool_size;
    j["queue_push"] = queue_push_name(s.queue_push);
    j["local_size"] = s.local_size;
    j["times"] = {{"load", s.times.load},
                  {"bvh_build", s.times.bvh_build},
                  {"kernel_build", s.times.kernel_build},
                  {"denoise", s.times.denoise},
                  {"kernels_from_cache", s.kernels_from_cache},
                  {"render", st.seconds},
                  {"kernels", st.kernel_seconds()}};
    j["samples"] = st.samples;
    j["closest_rays"] = st.closest_rays;
    j["shadow_rays"] = st.shadow_rays;
    j["nonfinite_samples"] = st.nonfinite_samples;
    j["lanes"] = {{"paths", st.lane_paths}, {"slots", st.lane_slots}};
    j["iterations"] = st.iterations;
    j["pool_occupancy"] = st.pool_occupancy();
    j["memory"] = {{"device_bytes", s.device_bytes},
                   {"pool_bytes", st.pool_bytes},
                   {"bytes_per_path", st.pool_size ? st.pool_bytes / st.pool_size : 0},
                   {"path_state_bytes_per_path", PathPool::state_bytes_per_path()},
                   {"traversal_bytes", s.traversal_bytes},
                   {"traversal_bytes_per_triangle", s.triangles ? double(s.traversal_bytes) / s.triangles : 0.0}};
    nlohmann::json stages = nlohmann::json::object();
    for (const StageTime& t : st.stages)
        if (t.launches) stages[t.name] = {{"launches", t.launches}, {"seconds", t.seconds}};
    j["stages"] = stages;
    j["path_lengths"] = st.path_lengths;
    // One row per read (CounterSnapshot::row()).
    nlohmann::json reads = nlohmann::json::array();
    for (const CounterSnapshot& c : st.counter_reads) reads.push_back(c.row());
    j["counter_read_columns"] = CounterSnapshot::kColumns;
    j["counter_reads"] = reads;
    write_file_atomically(path, j.dump(1) + "\n");
}

} // namespace wf
