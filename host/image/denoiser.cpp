// denoiser.cpp — see denoiser.h. The library is opened once, on first use,
// and kept open; a failed attempt is retried on the next call.
#include "image/denoiser.h"

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>
#include <vector>

#include <dlfcn.h>

#include "base/errors.h"
#include "image/oidn_api.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

constexpr const char* kOidnLibraryName = "libOpenImageDenoise.so.2";

// The functions denoiser.cpp calls, looked up in one opened library.
struct OidnLibrary {
    std::string path;
    oidn::NewDevice new_device = nullptr;
    oidn::CommitDevice commit_device = nullptr;
    oidn::ReleaseDevice release_device = nullptr;
    oidn::GetDeviceError get_device_error = nullptr;
    oidn::NewFilter new_filter = nullptr;
    oidn::SetSharedFilterImage set_shared_filter_image = nullptr;
    oidn::SetFilterBool set_filter_bool = nullptr;
    oidn::CommitFilter commit_filter = nullptr;
    oidn::ExecuteFilter execute_filter = nullptr;
    oidn::ReleaseFilter release_filter = nullptr;
};

// The places to try, in order (denoiser.h).
std::vector<std::string> oidn_candidate_paths() {
    if (const char* given = std::getenv("WF_OIDN_LIBRARY"); given && *given) return {given};
    std::vector<std::string> paths;
#ifdef WF_OIDN_VENV
    // pip puts the wheel under lib/pythonX.Y/site-packages/, X.Y the venv's Python.
    std::error_code ec;
    const fs::path venv_lib = fs::path(WF_OIDN_VENV) / "lib";
    bool found = false;
    for (fs::directory_iterator it(venv_lib, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path library = it->path() / "site-packages" / "pyoidn" / "oidn" / "lib" / kOidnLibraryName;
        if (fs::exists(library, ec)) {
            paths.push_back(library.string());
            found = true;
        }
    }
    if (!found) paths.push_back(WF_OIDN_VENV "/lib/python3*/site-packages/pyoidn/oidn/lib/" + std::string(kOidnLibraryName));
#endif
    // Beside the code running this: the site-packages `import wavefront` was
    // installed into, where `pip install pyoidn` puts the wheel too. The
    // module is its package's __init__, in site-packages/wavefront/.
    Dl_info self{};
    if (dladdr(reinterpret_cast<void*>(&oidn_candidate_paths), &self) && self.dli_fname) {
        const fs::path code(self.dli_fname);
        const bool package = code.filename().string().rfind("__init__.", 0) == 0;
        const fs::path beside = package ? code.parent_path().parent_path() : code.parent_path();
        paths.push_back((beside / "pyoidn" / "oidn" / "lib" / kOidnLibraryName).string());
    }
    paths.push_back(kOidnLibraryName); // the loader's search path
    return paths;
}

template <class F> void oidn_look_up(void* handle, const char* name, F& function, std::string& missing) {
    function = reinterpret_cast<F>(dlsym(handle, name));
    if (!function) missing += (missing.empty() ? "" : ", ") + std::string(name);
}

// The library opened from `path`, or nullopt with `error` set.
bool open_oidn_library(const std::string& path, OidnLibrary& lib, std::string& error) {
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = dlerror();
        error = why ? why : "cannot be opened";
        return false;
    }
    std::string missing;
    oidn_look_up(handle, "oidnNewDevice", lib.new_device, missing);
    oidn_look_up(handle, "oidnCommitDevice", lib.commit_device, missing);
    oidn_look_up(handle, "oidnReleaseDevice", lib.release_device, missing);
    oidn_look_up(handle, "oidnGetDeviceError", lib.get_device_error, missing);
    oidn_look_up(handle, "oidnNewFilter", lib.new_filter, missing);
    oidn_look_up(handle, "oidnSetSharedFilterImage", lib.set_shared_filter_image, missing);
    oidn_look_up(handle, "oidnSetFilterBool", lib.set_filter_bool, missing);
    oidn_look_up(handle, "oidnCommitFilter", lib.commit_filter, missing);
    oidn_look_up(handle, "oidnExecuteFilter", lib.execute_filter, missing);
    oidn_look_up(handle, "oidnReleaseFilter", lib.release_filter, missing);
    if (!missing.empty()) {
        dlclose(handle);
        error = path + " lacks " + missing + " (not Open Image Denoise 2.x)";
        return false;
    }
    lib.path = path;
    return true; // kept open for the life of the process
}

std::mutex g_oidn_mutex;
std::optional<OidnLibrary> g_oidn_library; // set once opened

const OidnLibrary& oidn_library() {
    std::lock_guard<std::mutex> lock(g_oidn_mutex);
    if (g_oidn_library) return *g_oidn_library;
    std::string looked, errors;
    for (const std::string& path : oidn_candidate_paths()) {
        OidnLibrary lib;
        std::string error;
        if (open_oidn_library(path, lib, error)) {
            g_oidn_library = lib;
            return *g_oidn_library;
        }
        looked += (looked.empty() ? "" : ", ") + path;
        // A file that is there but does not load says why; a missing one says nothing new.
        std::error_code ec;
        if (path.find('/') != std::string::npos && fs::exists(path, ec)) errors += "; " + error;
    }
    throw InputError("--denoise: Open Image Denoise not found (looked in " + looked + errors +
                     "): run scripts/setup.sh, or set WF_OIDN_LIBRARY to libOpenImageDenoise.so.2 from "
                     "`pip install pyoidn`");
}

// A device and its filters, released on every way out.
class OidnRun {
public:
    explicit OidnRun(const OidnLibrary& lib) : lib_(lib), device_(lib.new_device(oidn::OIDN_DEVICE_TYPE_CPU)) {
        if (!device_) throw DeviceError("--denoise: Open Image Denoise could not create a CPU device");
        lib_.commit_device(device_);
        check("creating its CPU device");
    }
    ~OidnRun() {
        for (oidn::OIDNFilter f : filters_) lib_.release_filter(f);
        lib_.release_device(device_);
    }
    OidnRun(const OidnRun&) = delete;
    OidnRun& operator=(const OidnRun&) = delete;

    // The RT filter with `images` as (name, pixels) and the bools set; runs it.
    void run(const std::vector<std::pair<const char*, float*>>& images,
             const std::vector<std::pair<const char*, bool>>& flags, uint32_t width, uint32_t height) {
        oidn::OIDNFilter filter = lib_.new_filter(device_, "RT");
        check("creating its RT filter");
        filters_.push_back(filter);
        for (const auto& [name, pixels] : images)
            lib_.set_shared_filter_image(filter, name, pixels, oidn::OIDN_FORMAT_FLOAT3, width, height, 0, 0, 0);
        for (const auto& [name, value] : flags) lib_.set_filter_bool(filter, name, value);
        lib_.commit_filter(filter);
        check("setting up its RT filter");
        lib_.execute_filter(filter);
        check("filtering");
    }

private:
    void check(const char* doing) {
        const char* message = nullptr;
        if (lib_.get_device_error(device_, &message) != oidn::OIDN_ERROR_NONE)
            throw DeviceError(std::string("--denoise: Open Image Denoise failed ") + doing + ": " +
                              (message ? message : "no message"));
    }

    const OidnLibrary& lib_;
    oidn::OIDNDevice device_;
    std::vector<oidn::OIDNFilter> filters_;
};

} // namespace

std::string denoiser_library() { return oidn_library().path; }

bool denoiser_available(std::string* why) {
    try {
        oidn_library();
        return true;
    } catch (const std::exception& e) {
        if (why) *why = e.what();
        return false;
    }
}

Image denoise(const Image& beauty, const Image& albedo, const Image& normal) {
    const size_t values = size_t{beauty.width} * beauty.height * 3;
    for (const Image* aux : {&albedo, &normal})
        if (aux->width != beauty.width || aux->height != beauty.height || aux->rgb.size() != values ||
            beauty.rgb.size() != values)
            throw InputError("--denoise: the albedo and normal must be the size of the image");
    const OidnLibrary& lib = oidn_library();
    Image color = beauty, clean_albedo = albedo, clean_normal = normal;
    Image output = beauty;
    output.stored = {};
    OidnRun oidn(lib);
    const uint32_t w = beauty.width, h = beauty.height;
    // Prefiltered in place, as OIDN's documentation shows for final frames.
    oidn.run({{"albedo", clean_albedo.rgb.data()}, {"output", clean_albedo.rgb.data()}}, {}, w, h);
    oidn.run({{"normal", clean_normal.rgb.data()}, {"output", clean_normal.rgb.data()}}, {}, w, h);
    oidn.run({{"color", color.rgb.data()},
              {"albedo", clean_albedo.rgb.data()},
              {"normal", clean_normal.rgb.data()},
              {"output", output.rgb.data()}},
             {{"hdr", true}, {"cleanAux", true}}, w, h);
    return output;
}

} // namespace wf
