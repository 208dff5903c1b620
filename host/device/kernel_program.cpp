// kernel_program.cpp — clBuildProgram with the log turned into a readable error.
//
// Two variables serve whoever ports the kernels to a new device: WF_KERNEL_OPTIONS
// adds to every program's build options (-cl-nv-verbose has NVIDIA's compiler
// report each kernel's registers and spills), and WF_KERNEL_BUILD_LOG names a
// file that each compile's whole log is appended to.
#include "device/kernel_program.h"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "base/errors.h"
#include "device/kernel_sources.h"

namespace wf {
namespace {

std::string first_error_line(const std::string& log) {
    std::istringstream in(log);
    std::string line, first_nonempty;
    while (std::getline(in, line)) {
        if (line.find("error") != std::string::npos) return line;
        if (first_nonempty.empty() && !line.empty()) first_nonempty = line;
    }
    return first_nonempty;
}

// A compiler's diagnostic says "error"; PoCL's failed cache write says only
// that the device failed to build the program.
bool names_a_source_error(const std::string& log) { return log.find("error") != std::string::npos; }

std::string build_options(const std::string& options) {
    const char* extra = std::getenv("WF_KERNEL_OPTIONS");
    return "-cl-std=CL1.2 " + options + (extra && *extra ? std::string(" ") + extra : std::string());
}

void append_build_log(const OpenClDevice& device, const std::string& source_path, const std::string& options,
                      const cl::Program& program) {
    const char* path = std::getenv("WF_KERNEL_BUILD_LOG");
    if (!path || !*path) return;
    std::ofstream out(path, std::ios::app);
    out << "== " << source_path << " on " << device.info.name << ": " << options << "\n"
        << program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device.info.device) << "\n";
}

} // namespace

std::string build_retrying_once(const std::function<std::string()>& attempt, const std::string& what,
                                std::string* warning) {
    const std::string first = attempt();
    if (first.empty() || names_a_source_error(first)) return first;
    const std::string second = attempt();
    if (second.empty())
        *warning = what + ": the first build failed without naming an error (\"" + first_error_line(first) +
                   "\"; processes sharing PoCL's cache folder can cause it) and the second worked";
    return second;
}

KernelProgram build_kernel_program(const OpenClDevice& device, const std::string& source_path,
                                   const std::string& options, const ProgramCache* cache) {
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const std::string source = expand_kernel_source(source_path);
    const std::string all_options = build_options(options);
    const std::string key = cache ? program_cache_key(device.info, all_options, source) : std::string();
    KernelProgram result;
    if (cache) {
        if (const auto binary = cache->load(key)) {
            try {
                result.program = cl::Program(device.context, {device.info.device}, cl::Program::Binaries{*binary});
                result.program.build({device.info.device}, all_options.c_str());
                result.from_cache = true;
                result.build_seconds = seconds();
                return result;
            } catch (const cl::Error&) {
                // A binary the driver will not load (a driver update it cannot see): compile instead.
            }
        }
    }
    const std::string log = build_retrying_once(
        [&]() -> std::string {
            result.program = cl::Program(device.context, source);
            try {
                result.program.build({device.info.device}, all_options.c_str());
            } catch (const cl::Error&) {
                append_build_log(device, source_path, all_options, result.program);
                const std::string failed = result.program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device.info.device);
                return failed.empty() ? std::string("the build failed, with an empty log") : failed;
            }
            append_build_log(device, source_path, all_options, result.program);
            return std::string();
        },
        "kernel " + source_path + " on " + device.info.name, &result.warning);
    if (!log.empty())
        throw DeviceError("kernel " + source_path + " failed to build on " + device.info.name + ": " +
                          first_error_line(log));
    if (cache) {
        const auto binaries = result.program.getInfo<CL_PROGRAM_BINARIES>();
        if (!binaries.empty() && !binaries.front().empty()) cache->store(key, binaries.front());
    }
    result.build_seconds = seconds();
    return result;
}

} // namespace wf
