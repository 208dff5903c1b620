// device_buffer.h — a read-only device buffer holding a copy of a vector.
// OpenCL has no empty buffers, so an empty vector uploads one zeroed element
// that no kernel reads.
#pragma once

#include <vector>

#include <CL/opencl.hpp>

namespace wf {

// Adds the buffer's size to `bytes`.
template <class T> cl::Buffer upload_read_only(const cl::Context& context, const std::vector<T>& data, size_t& bytes) {
    std::vector<T> storage = data.empty() ? std::vector<T>(1, T{}) : data;
    bytes += storage.size() * sizeof(T);
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, storage.size() * sizeof(T), storage.data());
}

} // namespace wf
