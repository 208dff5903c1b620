// cli.cpp — flags are declared with OpenImageIO's ArgParse (a dependency
// already), stored as text, then converted with range checks of our own so that
// "--spp abc" or "--spp 0" is an error rather than a silent zero.
#include "cli/cli.h"

#include <charconv>
#include <cmath>

#include <OpenImageIO/argparse.h>

#include "base/errors.h"
#include "scene/camera.h"

namespace wf {
namespace {

uint32_t parse_count(const std::string& flag, const std::string& text, uint64_t lo, uint64_t hi) {
    uint64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end)
        throw InputError(flag + " " + text + ": expected a whole number");
    if (value < lo || value > hi)
        throw InputError(flag + " " + text + ": must be between " + std::to_string(lo) + " and " +
                         std::to_string(hi));
    return static_cast<uint32_t>(value);
}

double parse_finite(const std::string& flag, const std::string& text) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value))
        throw InputError(flag + " " + text + ": expected a number");
    return value;
}

double parse_positive(const std::string& flag, const std::string& text) {
    const double value = parse_finite(flag, text);
    if (!(value > 0.0)) throw InputError(flag + " " + text + ": expected a positive number");
    return value;
}

// The index of `text` among a choice's names (render_settings.h), which are
// listed in the error otherwise.
uint32_t parse_choice(const std::string& flag, const std::string& text, const ChoiceNames& names) {
    std::string listed;
    for (uint32_t i = 0; i < names.size() && names[i]; ++i) {
        if (text == names[i]) return i;
        listed += (i ? "|" : "") + std::string(names[i]);
    }
    throw InputError(flag + " " + text + ": expected one of " + listed);
}

// A flag's help with its default, read from the settings' own initialisers.
std::string with_default(const std::string& help, const std::string& value) {
    return help + " (default: " + value + ")";
}
std::string with_default(const std::string& help, uint32_t value) { return with_default(help, std::to_string(value)); }

constexpr uint64_t kMaxSide = 1u << 15; // 32768: keeps every pixel index within 32 bits

std::string render_usage() {
    return "wavefront render SCENE.gltf|.glb [-o OUT] [flags]\n"
           "Renders a glTF scene by wavefront path tracing on an OpenCL device and writes the\n"
           "image (.exr: linear float radiance; .png and other 8-bit formats: sRGB).";
}

// `wavefront cache warm [--cache-dir DIR] [--device SPEC] SCENE...` or
// `wavefront cache clear [--cache-dir DIR]`.
CommandLine parse_cache_command(int argc, const char** argv) {
    CommandLine cl;
    const std::string action = argc > 2 ? argv[2] : "";
    if (action != "warm" && action != "clear")
        throw InputError("cache: expected warm or clear" + (action.empty() ? std::string() : ", not '" + action + "'"));
    cl.command = action == "warm" ? Command::CacheWarm : Command::CacheClear;
    for (int i = 3; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "--cache-dir" || word == "--device") {
            if (i + 1 >= argc) throw InputError("cache " + action + ": " + word + " needs a value");
            (word == "--cache-dir" ? cl.cache.directory : cl.cache.device) = argv[++i];
        } else if (!word.empty() && word[0] == '-') {
            throw InputError("cache " + action + ": unknown flag '" + word + "'");
        } else if (action == "warm") {
            cl.cache.scenes.push_back(word);
        } else {
            throw InputError("cache clear: unexpected argument '" + word + "'");
        }
    }
    if (action == "warm" && cl.cache.scenes.empty()) throw InputError("cache warm: no scene file given");
    if (action == "clear" && !cl.cache.device.empty()) throw InputError("cache clear: --device is for warm");
    return cl;
}

} // namespace

CommandLine parse_command_line(int argc, const char** argv) {
    CommandLine cl;
    const std::string first = argc > 1 ? argv[1] : "";
    if (argc < 2 || first == "--help" || first == "-h" || first == "help") {
        cl.help = "usage: wavefront render SCENE [flags]   render a glTF scene (see `wavefront render --help`)\n"
                  "       wavefront devices                list OpenCL platforms and devices\n"
                  "       wavefront cache warm SCENE...    compile the kernels those scenes need ahead of time\n"
                  "       wavefront cache clear            remove the compiled kernels kept on disk\n"
                  "         (both take --cache-dir DIR; warm takes --device SPEC)\n"
                  "       wavefront --version";
        return cl;
    }
    if (first == "--version") {
        cl.command = Command::Version;
        return cl;
    }
    if (first == "devices") {
        if (argc > 2) throw InputError(std::string("devices: unexpected argument '") + argv[2] + "'");
        cl.command = Command::Devices;
        return cl;
    }
    if (first == "cache") return parse_cache_command(argc, argv);
    if (first != "render")
        throw InputError("unknown command '" + first + "' (expected render, devices or cache)");

    RenderOptions& o = cl.render;
    std::vector<std::string> positional;
    OIIO::ArgParse ap;
    ap.intro(render_usage()).usage("wavefront render SCENE [flags]").exit_on_error(false);
    ap.add_help(false);
    ap.arg("filename").hidden().action([&](OIIO::cspan<const char*> a) { positional.emplace_back(a[0]); });
    ap.arg("-h").help("Print this help").store_true();
    ap.arg("--help").hidden().store_true();
    ap.arg("-o OUT").help(with_default("Output image; the extension picks the format", o.output));
    ap.arg("--spp N").help(with_default("Samples per pixel", o.settings.spp));
    ap.arg("--width N").help(with_default("Image width", std::to_string(kDefaultImageWidth) + ", or from --height and the camera's aspect"));
    ap.arg("--height N").help("Image height (default: from the width and the camera's aspect)");
    ap.arg("--max-depth N").help("Bounces per path; 1 is direct lighting only (default: unlimited, ended by roulette)");
    ap.arg("--seed N").help(with_default("Random seed; the same seed and device give the same bytes", o.settings.seed));
    ap.arg("--device SPEC").help("OpenCL device: an index from `wavefront devices`, cpu or gpu (default: first GPU, else first device)");
    ap.arg("--pool-size N").help("Paths in flight, at most the pixel count (default: " +
                                 std::to_string(kDefaultCpuPoolSize) + " for the wavefront on a CPU, where they stay in cache, " +
                                 std::to_string(kDefaultGpuPoolSize) + " otherwise)");
    ap.arg("--camera N").help("Index of the glTF camera to use (default: the first perspective camera, else one framing the scene)");
    ap.arg("--integrator I").help(with_default("wavefront (a kernel per stage, over queues) or megakernel (a kernel per path); the same image", integrator_name(o.settings.integrator)));
    ap.arg("--schedule S").help(with_default("The wavefront's launch order: refill, passes (pbrt-v4) or fullest (Cycles X)", schedule_name(o.settings.schedule)));
    ap.arg("--sort-materials").store_true().help("Sort the paths by the material they hit before shading, wavefront only (default: off)");
    ap.arg("--queue-push P").help(with_default("How kernels append to queues: group (one atomic per work-group), atomic (one per item) or scan (prefix sum)", queue_push_name(o.settings.queue_push)));
    ap.arg("--local-size N").help(with_default("Work-items per work-group, 16 to 1024", o.settings.local_size));
    ap.arg("--stats-json FILE").help("Write the render's statistics as JSON: stage times, rays, counters per iteration (default: none)");
    ap.separator("Sampling techniques:");
    ap.arg("--light-sampling T").help(with_default("How emitters are found: bsdf, nee or mis", choice_name(kLightSamplingNames, o.settings.light_sampling)));
    ap.arg("--hemisphere H").help(with_default("Lambertian sampling: uniform or cosine", choice_name(kHemisphereNames, o.settings.hemisphere)));
    ap.arg("--sampler S").help(with_default("Sample values: independent or sobol (Owen-scrambled)", choice_name(kSamplerNames, o.settings.sampler)));
    ap.arg("--env FILE").help("Environment light: an equirectangular .exr or .hdr, importance-sampled (default: none; a scene without any light gets a uniform white one)");
    ap.arg("--env-uniform L").help("Environment light of the same radiance L from every direction, instead of --env (default: none)");
    ap.arg("--env-rotate DEGREES").help("Turn the environment about the up (+y) axis (default: 0)");
    ap.arg("--env-scale S").help("Multiply the environment's radiance (default: 1)");
    ap.arg("--cache-dir DIR").help("Where compiled kernels are kept (default: $XDG_CACHE_HOME/wavefront, else ~/.cache/wavefront)");
    ap.arg("--no-specialize").store_true().help("Compile the generic kernels, every feature on, instead of those for the scene's features (default: off)");
    ap.arg("--aov A").help("Extra EXR layers: bounces, the radiance after 0, 1, ..., 6 and 7+ reflections (default: none)");
    ap.separator("Error against time:");
    ap.arg("--reference REF").help("Report MSE, relMSE and MAE against this image at every checkpoint (default: none)");
    ap.arg("--report CSV").help("Write the checkpoints to this CSV file: seconds,spp,mse,relmse,mae,relmse_estimate (default: none)");
    ap.arg("--report-every SECONDS").help("A checkpoint every this many seconds (default: at each doubling of spp)");
    ap.arg("--time SECONDS").help("Stop after this many seconds; then --spp, if given, is a cap (default: none)");
    ap.arg("--target-error X").help("Stop once the estimated relMSE is below X, checked from 16 spp on (default: none)");
    ap.separator("Long renders:");
    ap.arg("--checkpoint-every SECONDS").help("Write the render so far to OUT.partial.exr this often, atomically (default: never; Ctrl-C writes it too)");
    ap.arg("--resume PARTIAL").help("Go on from a partial render; the same scene, settings and seed are checked (default: none)");
    ap.arg("--quiet").store_true().help("No progress line on stderr (default: off)");

    // ArgParse expects argv[0]; ours is "render".
    if (ap.parse_args(argc - 1, argv + 1) < 0) throw InputError("render: " + ap.geterror());
    if (ap["h"].get<int>() || ap["help"].get<int>()) {
        ap.print_help(); // ArgParse prints to stdout itself
        return cl;
    }
    if (positional.size() != 1)
        throw InputError(positional.empty() ? "render: no scene file given"
                                            : "render: more than one scene file given ('" + positional[1] + "')");
    o.scene = positional[0];

    auto text = [&](const char* name) { return ap[name].get<std::string>(); };
    if (!text("o").empty()) o.output = text("o");
    if (!text("spp").empty()) o.settings.spp = parse_count("--spp", text("spp"), 1, 1u << 24);
    if (!text("width").empty()) o.width = parse_count("--width", text("width"), 1, kMaxSide);
    if (!text("height").empty()) o.height = parse_count("--height", text("height"), 1, kMaxSide);
    if (!text("max-depth").empty()) o.settings.max_depth = parse_count("--max-depth", text("max-depth"), 0, 1u << 20);
    if (!text("seed").empty()) o.settings.seed = parse_count("--seed", text("seed"), 0, UINT32_MAX);
    if (!text("pool-size").empty()) o.settings.pool_size = parse_count("--pool-size", text("pool-size"), 1, 1u << 26);
    if (!text("camera").empty()) o.camera = static_cast<int>(parse_count("--camera", text("camera"), 0, 1u << 20));
    o.device = text("device");
    if (!text("light-sampling").empty())
        o.settings.light_sampling = parse_choice("--light-sampling", text("light-sampling"), kLightSamplingNames);
    if (!text("hemisphere").empty())
        o.settings.hemisphere = parse_choice("--hemisphere", text("hemisphere"), kHemisphereNames);
    if (!text("sampler").empty())
        o.settings.sampler = parse_choice("--sampler", text("sampler"), kSamplerNames);
    if (!text("aov").empty()) {
        parse_choice("--aov", text("aov"), ChoiceNames{"bounces"});
        o.settings.bounce_layers = 8;
    }
    if (!text("integrator").empty())
        o.settings.integrator =
            static_cast<Integrator>(parse_choice("--integrator", text("integrator"), kIntegratorNames));
    if (!text("schedule").empty()) {
        o.settings.schedule =
            static_cast<Schedule>(parse_choice("--schedule", text("schedule"), kScheduleNames));
        if (o.settings.integrator == Integrator::Megakernel)
            throw InputError("--schedule orders the wavefront's stages; the megakernel has none");
    }
    if (!text("local-size").empty()) o.settings.local_size = parse_count("--local-size", text("local-size"), 16, 1024);
    if (!text("queue-push").empty())
        o.settings.queue_push =
            static_cast<QueuePush>(parse_choice("--queue-push", text("queue-push"), kQueuePushNames));
    o.settings.sort_materials = ap["sort-materials"].get<int>();
    if (o.settings.sort_materials && o.settings.integrator == Integrator::Megakernel)
        throw InputError("--sort-materials sorts the wavefront's queue; the megakernel has none");
    o.stats_json = text("stats-json");
    if (!text("checkpoint-every").empty())
        o.checkpoint_every = parse_positive("--checkpoint-every", text("checkpoint-every"));
    o.resume = text("resume");
    o.quiet = ap["quiet"].get<int>();
    o.settings.specialize = !ap["no-specialize"].get<int>();
    o.cache_dir = text("cache-dir");
    o.environment = text("env");
    if (!text("env-rotate").empty()) o.environment_rotate = float(parse_finite("--env-rotate", text("env-rotate")));
    if (!text("env-scale").empty()) o.environment_scale = float(parse_positive("--env-scale", text("env-scale")));
    if (o.environment.empty() && (!text("env-rotate").empty() || !text("env-scale").empty()))
        throw InputError("--env-rotate and --env-scale need --env");
    if (!text("env-uniform").empty()) {
        if (!o.environment.empty()) throw InputError("--env-uniform and --env exclude each other");
        o.environment_uniform = float(parse_positive("--env-uniform", text("env-uniform")));
    }
    o.reference = text("reference");
    o.report_csv = text("report");
    if (!text("report-every").empty()) o.progress.report_every = parse_positive("--report-every", text("report-every"));
    if (!text("time").empty()) o.progress.time_budget = parse_positive("--time", text("time"));
    if (!text("target-error").empty()) o.progress.target_relmse = parse_positive("--target-error", text("target-error"));
    // A time budget or a target error alone leaves the sample count open.
    const bool open_ended = o.progress.time_budget > 0.0 || o.progress.target_relmse > 0.0;
    o.progress.max_spp = text("spp").empty() && open_ended ? 0 : o.settings.spp;
    cl.command = Command::Render;
    return cl;
}

} // namespace wf
