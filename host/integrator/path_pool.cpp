// path_pool.cpp — allocation follows WF_PATH_STATE, so a field added there is
// allocated and bound here without further edits.
#include "integrator/path_pool.h"

#include <cstring>


namespace wf {
namespace {
// Host sizes of the types the path-state declaration uses.
using float4 = cl_float4;
using uint = cl_uint;
} // namespace

PathPool::PathPool(const cl::Context& context, uint32_t pool_size, bool shade_records) : size_(pool_size) {
#define WF_ALLOCATE_FIELD(type, name, what)                                                      \
    field_bytes_.push_back(sizeof(type));                                                       \
    fields_.emplace_back(context, CL_MEM_READ_WRITE, sizeof(type) * static_cast<size_t>(pool_size));
    WF_PATH_STATE(WF_ALLOCATE_FIELD)
#undef WF_ALLOCATE_FIELD
    queues = cl::Buffer(context, CL_MEM_READ_WRITE, queue_bytes_per_path() * static_cast<size_t>(pool_size));
    counters = cl::Buffer(context, CL_MEM_READ_WRITE, sizeof(cl_uint) * WF_COUNTER_COUNT);
    pixel_list = cl::Buffer(context, CL_MEM_READ_ONLY, sizeof(cl_uint));
    if (shade_records)
        this->shade_records =
            cl::Buffer(context, CL_MEM_READ_WRITE, shade_record_bytes_per_path() * static_cast<size_t>(pool_size));
}

void PathPool::set_pixel_list(const cl::CommandQueue& queue, const std::vector<uint32_t>& pixels) {
    const size_t bytes = sizeof(cl_uint) * pixels.size();
    if (bytes > pixel_list.getInfo<CL_MEM_SIZE>())
        pixel_list = cl::Buffer(queue.getInfo<CL_QUEUE_CONTEXT>(), CL_MEM_READ_ONLY, bytes);
    queue.enqueueWriteBuffer(pixel_list, CL_TRUE, 0, bytes, pixels.data());
}

size_t PathPool::state_bytes_per_path() {
    size_t bytes = 0;
#define WF_FIELD_BYTES(type, name, what) bytes += sizeof(type);
    WF_PATH_STATE(WF_FIELD_BYTES)
#undef WF_FIELD_BYTES
    return bytes;
}

size_t PathPool::bytes_per_path(bool shade_records) {
    return state_bytes_per_path() + (shade_records ? shade_record_bytes_per_path() : 0) + queue_bytes_per_path();
}

void PathPool::clear(const cl::CommandQueue& queue) const {
    for (size_t f = 0; f < fields_.size(); ++f)
        queue.enqueueFillBuffer(fields_[f], cl_uchar{0}, 0, field_bytes_[f] * size_);
}

void PathPool::restore_samples_started(const cl::CommandQueue& queue, const std::vector<uint32_t>& started) const {
    std::vector<cl_float4> radiance(started.size());
    for (size_t slot = 0; slot < started.size(); ++slot)
        std::memcpy(&radiance[slot].s[3], &started[slot], sizeof(uint32_t));
    queue.enqueueWriteBuffer(field(PathField::radiance), CL_TRUE, 0, sizeof(cl_float4) * started.size(),
                             radiance.data());
}

} // namespace wf
