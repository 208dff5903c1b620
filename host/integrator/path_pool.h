// path_pool.h — the device memory of the wavefront: one buffer per path-state
// field (include/wavefront/path_state.h), the queues, their counters, the
// list of pixels the slots trace when they are not a run of the image, and
// where the global-queue schedules run shade as two kernels, the records one
// leaves the other (include/wavefront/shade_record.h).
#pragma once

#include <cstdint>
#include <vector>

#include <CL/opencl.hpp>

#include "wavefront/path_state.h"
#include "wavefront/shade_record.h"
#include "wavefront/stage_graph.h"

namespace wf {

// One enumerator per path-state field, in declaration order.
enum class PathField {
#define WF_PATH_FIELD_ENUM(type, name, what) name,
    WF_PATH_STATE(WF_PATH_FIELD_ENUM)
#undef WF_PATH_FIELD_ENUM
};

class PathPool {
public:
    // `shade_records`: allocate them (the wavefront's global-queue schedules).
    PathPool(const cl::Context& context, uint32_t pool_size, bool shade_records = false);

    // Zeroes every path-state field, before a render starts.
    void clear(const cl::CommandQueue& queue) const;
    // Sets how many samples each of the first started.size() slots has
    // started (a resumed render, a unit of work), in the w lane of `radiance`
    // where the kernels keep it (kernels/path_view.h).
    void restore_samples_started(const cl::CommandQueue& queue, const std::vector<uint32_t>& started) const;

    // The pixels the slots trace from the next round on, in the order slots
    // take them (kernels/path_view.h): adaptive sampling's unfinished pixels.
    void set_pixel_list(const cl::CommandQueue& queue, const std::vector<uint32_t>& pixels);

    const cl::Buffer& field(PathField f) const { return fields_[static_cast<size_t>(f)]; }
    const std::vector<cl::Buffer>& fields() const { return fields_; } // in WF_PATH_STATE order

    uint32_t size() const { return size_; }
    // Device memory per path slot: its state (state_bytes_per_path), its
    // shade record where there are records, and one entry in every queue.
    static size_t bytes_per_path(bool shade_records);
    static size_t state_bytes_per_path();
    static constexpr size_t shade_record_bytes_per_path() { return sizeof(cl_float4) * WF_SHADE_RECORD_ROWS; }
    static constexpr size_t queue_bytes_per_path() { return sizeof(cl_uint) * WF_QUEUE_COUNT; }
    // The largest share of one buffer a path slot has: its record where there are records, else its queue entries.
    static constexpr size_t largest_bytes_per_path(bool shade_records) {
        return shade_records ? shade_record_bytes_per_path() : queue_bytes_per_path();
    }
    size_t bytes() const { return bytes_per_path(shade_records() != nullptr) * size_; }

    cl::Buffer queues;   // WF_QUEUE_COUNT regions of size() slot indices
    cl::Buffer counters; // WF_COUNTER_COUNT uints: queue lengths, then statistics
    cl::Buffer pixel_list; // set_pixel_list's; one unused entry until then
    cl::Buffer shade_records; // WF_SHADE_RECORD_ROWS rows of size() float4s, where asked for; else none

private:
    uint32_t size_;
    std::vector<cl::Buffer> fields_; // in WF_PATH_STATE order
    std::vector<size_t> field_bytes_; // bytes per slot of each field
};

} // namespace wf
