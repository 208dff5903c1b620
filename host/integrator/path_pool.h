// path_pool.h — the device memory of the wavefront: one buffer per path-state
// field (include/wavefront/path_state.h), the queues, their counters, and the
// list of pixels the slots trace when they are not a run of the image.
#pragma once

#include <cstdint>
#include <vector>

#include <CL/opencl.hpp>

#include "wavefront/path_state.h"

namespace wf {

// One enumerator per path-state field, in declaration order.
enum class PathField {
#define WF_PATH_FIELD_ENUM(type, name, what) name,
    WF_PATH_STATE(WF_PATH_FIELD_ENUM)
#undef WF_PATH_FIELD_ENUM
};

class PathPool {
public:
    PathPool(const cl::Context& context, uint32_t pool_size);

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
    // Device memory per path slot: its state (state_bytes_per_path) plus one entry in every queue.
    static size_t bytes_per_path();
    static size_t state_bytes_per_path();
    size_t bytes() const { return bytes_per_path() * size_; }

    cl::Buffer queues;   // WF_QUEUE_COUNT regions of size() slot indices
    cl::Buffer counters; // WF_COUNTER_COUNT uints: queue lengths, then statistics
    cl::Buffer pixel_list; // set_pixel_list's; one unused entry until then

private:
    uint32_t size_;
    std::vector<cl::Buffer> fields_; // in WF_PATH_STATE order
    std::vector<size_t> field_bytes_; // bytes per slot of each field
};

} // namespace wf
