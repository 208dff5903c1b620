// module.cpp — `import wavefront`: the renderer from Python, for sweeps and
// plots. render() takes every flag of `wavefront render` as a keyword
// (--pool-size as pool_size=...), parsed by the command line's own parser, so
// values are checked and errors worded as there; it renders through the
// render session's run_render(), as the command line does, and returns the
// image, the bounce layers and the statistics as NumPy arrays and plain
// objects. Errors arrive as wavefront.InputError (a ValueError: the input is
// at fault, exit status 2 on the command line) or wavefront.DeviceError (a
// RuntimeError: the machine), with the command line's one-line message.
// `python -m wavefront` (__main__.py) runs the command line itself, through
// _main().
#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include <pybind11/eval.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "base/errors.h"
#include "cli/cli.h"
#include "cli/run_command.h"
#include "cli/version_text.h"
#include "device/opencl_device.h"
#include "gltf/gltf_loader.h"
#include "image/image_io.h"
#include "python/render_keywords.h"
#include "session/exit_status.h"
#include "session/run_render.h"

namespace py = pybind11;

namespace wf {
namespace {

// A loaded scene, and the file it came from.
struct PyScene {
    std::string path;
    int camera = -1;
    Instancing instancing = Instancing::Large;
    Scene scene;
};

// The render's result as Python sees it.
struct PyResult {
    py::array_t<float> image, variance;
    py::object noisy = py::none(); // with denoise=True: the image before denoising
    py::dict bounce_layers, aovs;
    RenderSummary summary;
    std::vector<Checkpoint> checkpoints;
};

py::array_t<float> to_array(const Image& image) {
    py::array_t<float> a({size_t{image.height}, size_t{image.width}, size_t{3}});
    std::copy(image.rgb.begin(), image.rgb.end(), a.mutable_data());
    return a;
}

// A layer that holds one value a pixel in each channel, as height x width.
py::array_t<float> first_channel(const Image& image) {
    py::array_t<float> a({size_t{image.height}, size_t{image.width}});
    for (size_t p = 0; p < size_t(a.size()); ++p) a.mutable_data()[p] = image.rgb[3 * p];
    return a;
}

RenderOptions parse_render(const std::string& scene, const py::dict& options) {
    const std::vector<std::string> words = render_words(scene, options);
    std::vector<const char*> argv;
    for (const std::string& w : words) argv.push_back(w.c_str());
    const CommandLine cl = parse_command_line(static_cast<int>(argv.size()), argv.data());
    if (cl.command != Command::Render) throw InputError("render: " + cl.help);
    return cl.render;
}

// Ctrl-C during a render: Python runs its own handler only between bytecodes,
// which a render in C++ never reaches, so the render installs one that stops it.
std::atomic<int> g_stop{0};
extern "C" void stop_render(int sig) { g_stop.store(sig); }

class InterruptScope {
public:
    InterruptScope() {
        g_stop.store(0);
        struct sigaction action {};
        action.sa_handler = stop_render;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &previous_);
    }
    ~InterruptScope() { sigaction(SIGINT, &previous_, nullptr); }

private:
    struct sigaction previous_ {};
};

// reference= given as an array: the image the render is compared with,
// handed to the render in memory (RenderHooks::reference); None otherwise.
std::optional<Image> array_reference(py::dict& options) {
    if (!options.contains("reference") || !py::isinstance<py::array>(options["reference"])) return std::nullopt;
    const auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(options["reference"]);
    if (!a || a.ndim() != 3 || a.shape(2) != 3)
        throw py::type_error("render(): reference takes a path or a height x width x 3 array");
    Image image;
    image.width = uint32_t(a.shape(1));
    image.height = uint32_t(a.shape(0));
    image.rgb.assign(a.data(), a.data() + a.size());
    PyDict_DelItemString(options.ptr(), "reference"); // not a flag's text
    return image;
}

PyResult render(py::object scene, std::optional<py::function> progress, const py::kwargs& keywords) {
    const bool loaded = py::isinstance<PyScene>(scene);
    const std::string path = loaded ? scene.cast<const PyScene&>().path
                                    : py::str(py::module_::import("os").attr("fspath")(scene)).cast<std::string>();
    py::dict options(keywords);
    const std::optional<Image> reference = array_reference(options);
    RenderOptions parsed = parse_render(path, options);
    // None is the flag's default, as if not given (the signature shows None).
    const auto given = [&](const char* name) { return options.contains(name) && !options[name].is_none(); };
    const bool write_image = given("output");
    if (!given("quiet")) parsed.quiet = true; // no table, report or progress line on the terminal
    if (loaded) { // the scene's camera, unless another is asked for
        const int camera = scene.cast<const PyScene&>().camera;
        if (!given("camera")) parsed.camera = camera;
        if (parsed.camera != camera)
            throw InputError("render: camera " + std::to_string(parsed.camera) + " is not the one " + path +
                             " was loaded with (" + std::to_string(camera) + "); load it again with that camera");
        const Instancing instancing = scene.cast<const PyScene&>().instancing;
        if (!given("instancing")) parsed.instancing = instancing;
        if (parsed.instancing != instancing)
            throw InputError(std::string("render: instancing ") + kInstancingNames[size_t(parsed.instancing)] +
                             " is not the one " + path + " was loaded with (" + kInstancingNames[size_t(instancing)] +
                             "); load it again with that instancing");
    }

    PyResult result;
    FilmReadout film;
    Image denoised;
    RenderHooks hooks;
    hooks.denoised = &denoised;
    hooks.scene = loaded ? &scene.cast<const PyScene&>().scene : nullptr;
    hooks.reference = reference ? &*reference : nullptr;
    hooks.stop = &g_stop;
    hooks.film = &film;
    hooks.write_image = write_image;
    hooks.on_checkpoint = [&](const Checkpoint& c) { result.checkpoints.push_back(c); };
    std::optional<py::error_already_set> raised; // by the callback, raised again once the render has stopped
    size_t reads_given = 0; // the callback sees the counter reads that came since its last call
    if (progress)
        hooks.on_progress = [&](const RenderStats& s) {
            py::gil_scoped_acquire gil;
            if (raised) return;
            RenderStats recent = s.without_counter_reads();
            if (s.counter_reads.size() >= reads_given)
                recent.counter_reads.assign(s.counter_reads.begin() + reads_given, s.counter_reads.end());
            reads_given = s.counter_reads.size();
            try {
                (*progress)(recent);
            } catch (py::error_already_set& e) {
                raised = std::move(e);
                g_stop.store(SIGINT);
            }
        };
    {
        InterruptScope interrupt;
        py::gil_scoped_release released;
        std::ostream quiet(nullptr);
        result.summary = run_render(parsed, quiet, quiet, hooks);
    }
    result.image = to_array(film.mean);
    if (!denoised.rgb.empty()) { // denoise=True
        result.noisy = result.image;
        result.image = to_array(denoised);
    }
    result.variance = to_array(film.variance_of_mean);
    if (film.albedo) result.aovs["albedo"] = to_array(*film.albedo);
    if (film.normal) result.aovs["normal"] = to_array(*film.normal);
    if (film.depth) result.aovs["depth"] = first_channel(*film.depth);      // the distance
    if (film.samples) result.aovs["samples"] = first_channel(*film.samples); // each pixel's count
    for (size_t l = 0; l < film.bounce_layers.size(); ++l)
        result.bounce_layers[py::str(bounce_layer_name(l, film.bounce_layers.size()))] = to_array(film.bounce_layers[l]);
    // A render stopped by the callback's exception or by Ctrl-C keeps what it
    // computed: the exception carries it as `result`.
    if (raised) {
        raised->value().attr("result") = py::cast(std::move(result));
        throw std::move(*raised);
    }
    if (result.summary.interrupted_by) {
        const py::object interrupt = py::reinterpret_borrow<py::object>(PyExc_KeyboardInterrupt)();
        interrupt.attr("result") = py::cast(std::move(result));
        PyErr_SetObject(PyExc_KeyboardInterrupt, interrupt.ptr());
        throw py::error_already_set();
    }
    return result;
}

// The counter reads as rows of CounterSnapshot::row(), as the stats JSON has them.
py::array_t<uint32_t> counter_reads(const RenderStats& s) {
    const size_t columns = CounterSnapshot::kColumns.size();
    py::array_t<uint32_t> a({s.counter_reads.size(), columns});
    for (size_t i = 0; i < s.counter_reads.size(); ++i) {
        const auto row = s.counter_reads[i].row();
        std::copy(row.begin(), row.end(), a.mutable_data() + i * columns);
    }
    return a;
}

py::dict stages(const RenderStats& s) {
    py::dict d;
    for (const StageTime& t : s.stages)
        if (t.launches) d[py::str(t.name)] = py::dict(py::arg("launches") = t.launches, py::arg("seconds") = t.seconds);
    return d;
}

} // namespace
} // namespace wf

PYBIND11_MODULE(wavefront, m) {
    using namespace wf;
    m.doc() = "Wavefront path tracing on OpenCL devices: render glTF scenes and read their statistics.";
    m.attr("__version__") = WF_VERSION;

    static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
    static py::exception<DeviceError> device_error(m, "DeviceError", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        if (!p) return;
        try {
            std::rethrow_exception(p);
        } catch (py::error_already_set&) {
            throw;
        } catch (py::builtin_exception&) {
            throw;
        } catch (...) {
            const Failure failure = describe_exception();
            PyObject* type = failure.exit_code == 2 ? input_error.ptr() : device_error.ptr();
            PyErr_SetString(type, failure.message.c_str());
        }
    });

    py::class_<DeviceInfo>(m, "Device", "An OpenCL device, as `wavefront devices` lists it")
        .def_readonly("index", &DeviceInfo::index)
        .def_readonly("name", &DeviceInfo::name)
        .def_readonly("type", &DeviceInfo::type)
        .def_readonly("platform", &DeviceInfo::platform)
        .def_readonly("version", &DeviceInfo::version)
        .def_readonly("compute_units", &DeviceInfo::compute_units)
        .def_readonly("global_memory", &DeviceInfo::global_memory)
        .def("__repr__", [](const DeviceInfo& d) { return "<wavefront.Device " + std::to_string(d.index) + ": " + d.name + ">"; });
    m.def("devices", &list_devices, "Every OpenCL device of every platform, with its index for device=");

    py::class_<PyScene>(m, "Scene", "A glTF scene, loaded and checked")
        .def_readonly("path", &PyScene::path)
        .def_property_readonly("triangles", [](const PyScene& s) { return s.scene.triangle_count(); })
        .def_property_readonly("placed_triangles", [](const PyScene& s) { return s.scene.placed_triangle_count(); })
        .def_property_readonly("materials", [](const PyScene& s) { return s.scene.materials.size(); })
        .def_property_readonly("punctual_lights", [](const PyScene& s) { return s.scene.punctual_lights.size(); })
        .def_property_readonly("has_camera", [](const PyScene& s) { return s.scene.camera.has_value(); })
        .def_property_readonly("warnings", [](const PyScene& s) { return s.scene.warnings; })
        .def("__repr__", [](const PyScene& s) {
            return "<wavefront.Scene " + s.path + ": " + std::to_string(s.scene.triangle_count()) + " triangles>";
        });
    m.def(
        "load_scene",
        [](const std::filesystem::path& file, int camera, const std::string& instancing) {
            const std::string path = file.string();
            const std::optional<uint32_t> mode = choice_value(kInstancingNames, instancing);
            if (!mode) throw InputError("load_scene: instancing '" + instancing + "' is not one of off, large, all");
            const auto chosen = static_cast<Instancing>(*mode);
            return PyScene{path, camera, chosen, load_gltf(path, LoadOptions{camera, chosen})};
        },
        py::arg("path"), py::arg("camera") = -1, py::arg("instancing") = "large",
        "Loads a .gltf or .glb file; camera=-1 is its first camera; instancing as render's");

    py::class_<RenderStats>(m, "Stats", "What a render did: counts, kernel times, queue counters")
        .def_readonly("seconds", &RenderStats::seconds, "wall time rendering")
        .def_readonly("samples", &RenderStats::samples)
        .def_readonly("closest_rays", &RenderStats::closest_rays)
        .def_readonly("shadow_rays", &RenderStats::shadow_rays)
        .def_readonly("nonfinite_samples", &RenderStats::nonfinite_samples)
        .def_readonly("lane_paths", &RenderStats::lane_paths, "BSDF queries answered in the group schedule's lanes")
        .def_readonly("lane_slots", &RenderStats::lane_slots, "lanes those took, filled or not")
        .def_readonly("iterations", &RenderStats::iterations)
        .def_readonly("pool_size", &RenderStats::pool_size)
        .def_readonly("pool_bytes", &RenderStats::pool_bytes)
        .def_property_readonly("integrator", [](const RenderStats& s) { return integrator_name(s.integrator); })
        .def_property_readonly(
            "schedule",
            [](const RenderStats& s) -> std::optional<std::string> {
                if (s.integrator == Integrator::Megakernel) return std::nullopt; // it has no stages to order
                return std::string(schedule_name(s.schedule));
            },
            "the wavefront's launch order; None for the megakernel")
        .def_property_readonly("kernel_seconds", &RenderStats::kernel_seconds)
        .def_property_readonly("pool_occupancy", &RenderStats::pool_occupancy)
        .def_property_readonly("stages", &stages, "per stage kernel: launches and seconds (profiling events)")
        .def_property_readonly("path_lengths",
                               [](const RenderStats& s) { return py::array_t<uint64_t>(s.path_lengths.size(), s.path_lengths.data()); },
                               "finished paths by bounces: bucket 0 holds 0, bucket b holds [2^(b-1), 2^b)")
        .def_property_readonly("counter_reads", &counter_reads,
                               "one row per read of the counters, as counter_read_columns names them: the "
                               "queues' lengths as read (the group schedule: the paths that entered each queue "
                               "since the previous read), then closest rays, shadow rays and samples since the "
                               "previous read; in progress(stats), the reads since its previous call")
        .def("__repr__",
             [](const RenderStats& s) {
                 std::ostringstream text;
                 text << "<wavefront.Stats " << integrator_name(s.integrator)
                      << (s.integrator == Integrator::Megakernel ? "" : std::string(", ") + schedule_name(s.schedule))
                      << ": " << s.samples << " samples in " << s.seconds << " s, " << s.iterations << " iterations>";
                 return text.str();
             })
        .def_property_readonly_static("counter_read_columns", [](py::object) {
            return std::vector<std::string>(CounterSnapshot::kColumns.begin(), CounterSnapshot::kColumns.end());
        });

    py::class_<DeviceShare>(m, "DeviceShare", "One device's part in a render over several")
        .def_readonly("device", &DeviceShare::device)
        .def_readonly("samples", &DeviceShare::samples)
        .def_readonly("units", &DeviceShare::units)
        .def_readonly("busy_seconds", &DeviceShare::busy_seconds)
        .def_readonly("transfer_seconds", &DeviceShare::transfer_seconds);

    py::class_<Checkpoint>(m, "Checkpoint", "The state after a round: time, spp and error")
        .def_readonly("seconds", &Checkpoint::seconds)
        .def_readonly("spp", &Checkpoint::spp)
        .def_property_readonly("relmse", [](const Checkpoint& c) { return c.error ? std::optional<double>(c.error->relmse) : std::nullopt; })
        .def_readonly("relmse_estimate", &Checkpoint::relmse_estimate)
        .def_readonly("pixels_sampling", &Checkpoint::pixels_sampling, "pixels the next round continues")
        .def("__repr__", [](const Checkpoint& c) {
            std::ostringstream text;
            text << "<wavefront.Checkpoint " << c.spp << " spp at " << c.seconds << " s";
            if (c.error) text << ", relMSE " << c.error->relmse;
            if (c.relmse_estimate) text << ", estimated relMSE " << *c.relmse_estimate;
            return text.str() + ">";
        });

    py::class_<PyResult>(m, "Result", "A finished render")
        .def_readonly("image", &PyResult::image,
                      "linear radiance, height x width x 3, float32; with denoise=True, denoised")
        .def_readonly("noisy", &PyResult::noisy, "with denoise=True: the image before denoising; else None")
        .def_readonly("variance", &PyResult::variance, "the variance of each pixel's mean")
        .def_readonly("bounce_layers", &PyResult::bounce_layers, "with aov='bounces': name -> image")
        .def_readonly("aovs", &PyResult::aovs,
                      "with aov=['albedo', 'normal', 'depth']: the first hit's mean base colour and shading normal "
                      "(height x width x 3) and distance (height x width); 0 where the camera ray escapes; with "
                      "aov='samples', the samples each pixel took (height x width)")
        .def_readonly("checkpoints", &PyResult::checkpoints)
        .def_property_readonly("stats", [](const PyResult& r) { return r.summary.stats; })
        .def_property_readonly("spp", [](const PyResult& r) { return r.summary.spp; })
        .def_property_readonly("device", [](const PyResult& r) { return r.summary.device; })
        .def_property_readonly("features", [](const PyResult& r) { return r.summary.features; })
        .def_property_readonly("device_bytes", [](const PyResult& r) { return r.summary.device_bytes; })
        .def_property_readonly("shares", [](const PyResult& r) { return r.summary.shares; })
        .def_property_readonly("kernel_build_seconds", [](const PyResult& r) { return r.summary.times.kernel_build; })
        .def_property_readonly("denoise_seconds", [](const PyResult& r) { return r.summary.times.denoise; })
        .def_property_readonly("report", [](const PyResult& r) {
            std::ostringstream out;
            print_report(out, r.summary);
            return out.str();
        }, "the command line's closing report")
        .def("__repr__", [](const PyResult& r) {
            return "<wavefront.Result " + std::to_string(r.summary.width) + " x " + std::to_string(r.summary.height) +
                   ", " + std::to_string(r.summary.spp) + " spp on " + r.summary.device + ">";
        });

    m.def(
        "write_image",
        [](const std::filesystem::path& path, py::array_t<float, py::array::c_style | py::array::forcecast> rgb,
           float exposure, bool half) {
            if (rgb.ndim() != 3 || rgb.shape(2) != 3) throw py::type_error("write_image(): image takes a height x width x 3 array");
            Image image;
            image.width = uint32_t(rgb.shape(1));
            image.height = uint32_t(rgb.shape(0));
            image.rgb.assign(rgb.data(), rgb.data() + rgb.size());
            check_can_write(path.string());
            write_image(path.string(), image, ImageMetadata{}, {}, ImageEncoding{half, exposure});
        },
        py::arg("path"), py::arg("image"), py::arg("exposure") = 0.0f, py::arg("half") = false,
        "Writes linear radiance (height x width x 3) as the command line does: the extension picks the format; "
        "8-bit formats get 2^exposure and the sRGB curve, float formats keep radiance (half=True: 16-bit)");
    m.def(
        "srgb",
        [](py::array_t<float, py::array::c_style | py::array::forcecast> rgb, float exposure) {
            py::array_t<float> out(std::vector<py::ssize_t>(rgb.shape(), rgb.shape() + rgb.ndim()));
            const float scale = std::exp2(exposure);
            for (py::ssize_t i = 0; i < rgb.size(); ++i) out.mutable_data()[i] = srgb_encode(rgb.data()[i] * scale);
            return out;
        },
        py::arg("image"), py::arg("exposure") = 0.0f,
        "The display image of linear radiance: scaled by 2^exposure (the command line's --exposure), clipped to "
        "[0, 1] and sRGB-encoded, as an 8-bit output holds it; for matplotlib's imshow");
    m.def(
        "read_image", [](const std::filesystem::path& path) { return to_array(read_image(path.string())); },
        py::arg("path"),
        "An image file's RGB as linear float32 (8-bit formats are decoded from sRGB), height x width x 3");

    // `python -m wavefront ARGS` (__main__.py): the program's command line and
    // exit status, its output on the process's own stdout and stderr.
    m.def(
        "_main",
        [](const std::vector<std::string>& args) {
            std::vector<const char*> argv{"wavefront"};
            for (const std::string& a : args) argv.push_back(a.c_str());
            py::gil_scoped_release released;
            const int status = run_command_line(static_cast<int>(argv.size()), argv.data(), version_text);
            std::cout.flush();
            return status;
        },
        py::arg("args"));

    // render() is a Python function, so that it can carry the signature of
    // every keyword (render_keywords.h); _render does the work.
    m.def("_render", &render, py::arg("scene"), py::arg("progress") = py::none());
    py::exec("def render(scene, progress=None, **keywords):\n"
             "    return _render(scene, progress, **keywords)\n",
             m.attr("__dict__"));
    describe_render(m.attr("render"),
                    "Renders a scene (a path or a Scene) with `wavefront render`'s flags as keywords: spp=64, "
                    "pool_size=65536,\nschedule='refill', device='all', aov='bounces', output='out.exr', "
                    "reference=an array or a path, ...\nprogress(stats) is called as the render goes; Ctrl-C "
                    "stops it cleanly and raises KeyboardInterrupt.\nNothing is written unless output= is "
                    "given.");
}
