// kernel_source.cpp — `wavefront_kernel_source`: the program the renderer
// would build for a scene on a device of a given kind, as one expanded
// OpenCL C file and its build options, so that other compilers (the GPU
// instruction-set report, bench/gpu_isa.py) compile exactly what the host
// compiles (render/device_renderer.h, device/kernel_sources.h).
//
//   wavefront_kernel_source SCENE.gltf|.glb|--all-features --device-type cpu|gpu
//                           [--integrator wavefront|megakernel] [--schedule NAME] -o OUT.cl
//
// Prints the build options on stdout. A cpu device is taken to have 8-float
// vectors (AVX2), which is what the group schedule's lanes depend on; a gpu
// one 1, as OpenCL GPUs report.
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "base/errors.h"
#include "session/exit_status.h"
#include "device/kernel_sources.h"
#include "device/scene_features.h"
#include "gltf/gltf_loader.h"
#include "render/device_renderer.h"

namespace wf::bench {
namespace {

template <class T> T choice(const ChoiceNames& names, const std::string& flag, const std::string& value) {
    if (const std::optional<uint32_t> v = choice_value(names, value)) return static_cast<T>(*v);
    throw InputError(flag + " " + value + ": not one of the choices");
}

int run(int argc, const char** argv) {
    const std::string usage = "usage: wavefront_kernel_source SCENE.gltf|.glb|--all-features --device-type cpu|gpu "
                              "[--integrator wavefront|megakernel] [--schedule NAME] -o OUT.cl";
    std::string scene, out, type;
    bool all_features = false;
    RenderSettings settings;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--all-features") all_features = true;
        else if (a == "--device-type" && has_value) type = argv[++i];
        else if (a == "--integrator" && has_value) settings.integrator = choice<Integrator>(kIntegratorNames, a, argv[++i]);
        else if (a == "--schedule" && has_value) settings.schedule = choice<Schedule>(kScheduleNames, a, argv[++i]);
        else if (a == "-o" && has_value) out = argv[++i];
        else if (a.rfind("-", 0) != 0 && scene.empty()) scene = a;
        else throw InputError("unexpected argument '" + a + "'; " + usage);
    }
    if ((scene.empty() == !all_features) || out.empty() || (type != "cpu" && type != "gpu")) throw InputError(usage);
    DeviceInfo device;
    device.type = type;
    device.native_float_width = type == "cpu" ? 8u : 1u;
    const SceneFeatures features = all_features ? SceneFeatures::all() : scene_features(load_gltf(scene));
    const RenderProgramSource source = render_program_source(device, features, settings);
    std::ofstream file(out, std::ios::binary);
    file << expand_kernel_source(source.root);
    if (!file.flush()) throw InputError(out + ": cannot write the expanded source");
    std::cout << source.options << "\n";
    return 0;
}

} // namespace
} // namespace wf::bench

int main(int argc, const char** argv) {
    try {
        return wf::bench::run(argc, argv);
    } catch (...) {
        return wf::report_exception();
    }
}
