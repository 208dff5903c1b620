// opencl_device.cpp — platform and device enumeration through the ICD loader.
#include "device/opencl_device.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "base/errors.h"
#include "base/output_files.h"

namespace wf {
namespace {

std::string device_type_name(cl_device_type type) {
    if (type & CL_DEVICE_TYPE_GPU) return "gpu";
    if (type & CL_DEVICE_TYPE_CPU) return "cpu";
    if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
    return "other";
}

bool is_index(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
}

// PoCL offers no device when it cannot create its kernel cache (an unwritable
// or missing HOME, say), which would otherwise read as a broken driver. Its
// folder, as PoCL chooses it: POCL_CACHE_DIR, else $XDG_CACHE_HOME/pocl, else
// $HOME/.cache/pocl. Empty when that folder can be made and written.
std::string pocl_cache_problem() {
    namespace fs = std::filesystem;
    const char* pocl = std::getenv("POCL_CACHE_DIR");
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    fs::path folder;
    std::string from;
    if (pocl && *pocl) folder = pocl, from = "POCL_CACHE_DIR";
    else if (xdg && *xdg) folder = fs::path(xdg) / "pocl", from = "XDG_CACHE_HOME";
    else if (home && *home) folder = fs::path(home) / ".cache" / "pocl", from = "HOME";
    else return "";
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (!ec && folder_takes_new_files(folder)) return "";
    return "PoCL cannot create its kernel cache in " + folder.string() + " (from " + from +
           "), so it offers no device: set POCL_CACHE_DIR to a writable folder";
}

} // namespace

std::vector<DeviceInfo> list_devices() {
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error&) {
        // The ICD loader reports "no platform" as CL_PLATFORM_NOT_FOUND_KHR.
    }
    if (platforms.empty())
        throw DeviceError("no OpenCL platform found: install an OpenCL driver, e.g. "
                          "`apt-get install pocl-opencl-icd` for the CPU");
    std::vector<DeviceInfo> result;
    for (const cl::Platform& platform : platforms) {
        std::vector<cl::Device> devices;
        try {
            platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
        } catch (const cl::Error&) {
            continue; // a platform with no devices
        }
        for (const cl::Device& d : devices) {
            DeviceInfo info;
            info.index = static_cast<int>(result.size());
            info.platform = platform.getInfo<CL_PLATFORM_NAME>();
            info.name = d.getInfo<CL_DEVICE_NAME>();
            info.type = device_type_name(d.getInfo<CL_DEVICE_TYPE>());
            info.version = d.getInfo<CL_DEVICE_VERSION>();
            info.driver = d.getInfo<CL_DRIVER_VERSION>();
            info.compute_units = d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
            info.global_memory = d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
            info.max_allocation = d.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
            info.native_float_width = d.getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>();
            info.global_cache = d.getInfo<CL_DEVICE_GLOBAL_MEM_CACHE_SIZE>();
            info.device = d;
            result.push_back(info);
        }
    }
    if (result.empty()) {
        for (const cl::Platform& platform : platforms)
            if (platform.getInfo<CL_PLATFORM_NAME>() == "Portable Computing Language")
                if (const std::string problem = pocl_cache_problem(); !problem.empty()) throw DeviceError(problem);
        throw DeviceError("OpenCL platforms found, but no device: check the driver installation");
    }
    return result;
}

namespace {

DeviceInfo choose_from(const std::vector<DeviceInfo>& devices, const std::string& spec) {
    if (spec.empty()) {
        for (const DeviceInfo& d : devices)
            if (d.type == "gpu") return d;
        return devices.front();
    }
    if (is_index(spec)) {
        const size_t i = spec.size() < 9 ? std::stoul(spec) : devices.size();
        if (i < devices.size()) return devices[i];
        throw InputError("--device " + spec + ": no such device (there are " +
                         std::to_string(devices.size()) + "; see `wavefront devices`)");
    }
    for (const DeviceInfo& d : devices)
        if (d.type == spec) return d;
    throw InputError("--device " + spec + ": no device of that type (expected an index, cpu or gpu; "
                     "see `wavefront devices`)");
}

OpenClDevice open(const DeviceInfo& info) {
    OpenClDevice d;
    d.info = info;
    d.context = cl::Context(d.info.device);
    d.queue = cl::CommandQueue(d.context, d.info.device, CL_QUEUE_PROFILING_ENABLE);
    return d;
}

} // namespace

DeviceInfo choose_device(const std::string& spec) { return choose_from(list_devices(), spec); }

std::vector<DeviceInfo> choose_devices(const std::string& spec) {
    const std::vector<DeviceInfo> devices = list_devices();
    if (spec == "all") return devices;
    std::vector<DeviceInfo> chosen;
    size_t from = 0;
    do {
        const size_t comma = std::min(spec.find(',', from), spec.size());
        if (comma == from && spec.size() > 0) throw InputError("--device " + spec + ": an empty entry in the list");
        const DeviceInfo d = choose_from(devices, spec.substr(from, comma - from));
        for (const DeviceInfo& c : chosen)
            if (c.index == d.index)
                throw InputError("--device " + spec + ": device " + std::to_string(d.index) + " is named twice");
        chosen.push_back(d);
        from = comma + 1;
    } while (from <= spec.size());
    return chosen;
}

OpenClDevice open_device(const std::string& spec) { return open(choose_device(spec)); }

std::vector<OpenClDevice> open_devices(const std::string& spec) {
    std::vector<OpenClDevice> opened;
    for (const DeviceInfo& d : choose_devices(spec)) opened.push_back(open(d));
    return opened;
}

} // namespace wf
