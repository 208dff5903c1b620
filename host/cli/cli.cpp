// cli.cpp — the command line, declared with CLI11: each flag once, with its
// help, its default (read from the variable it fills) and its check (a range
// or a list of choices), so that `--help`, the defaults and the errors cannot
// disagree. `--opt value` and `--opt=value` both work, and `render --config
// FILE` reads any flag from a TOML file. A CLI11 error becomes an InputError
// whose one line names the command and the flag.
#include "cli/cli.h"

#include <cctype>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <CLI/CLI.hpp>

#include "base/errors.h"
#include "cli/config_file.h"
#include "image/image_io.h"
#include "scene/camera.h"

namespace wf {
namespace {

// A value as a stream writes it: a number in as few digits as it needs ("1", "-1.5").
template <class T> std::string as_text(const T& value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

constexpr uint32_t kMaxSide = 1u << 15; // 32768: keeps every pixel index within 32 bits

// A whole number in [lo, hi], checked on the text so that "abc" and "-5" are
// named as such rather than converted to something else.
CLI::Validator whole_number(uint64_t lo, uint64_t hi) {
    const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            const bool negative = text.size() > 1 && text[0] == '-' &&
                                  text.find_first_not_of("0123456789", 1) == std::string::npos;
            if (negative) return text + " is not in " + range;
            if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
                return "'" + text + "' is not a whole number";
            if (text.size() > 12 || std::stoull(text) < lo || std::stoull(text) > hi)
                return text + " is not in " + range;
            return "";
        },
        "in " + range);
}

// A bounce count in [0, hi], or `unlimited` (WF_UNLIMITED_DEPTH).
CLI::Validator depth_limit(uint32_t hi) {
    const CLI::Validator number = whole_number(0, hi);
    return CLI::Validator(
        [number](std::string& text) -> std::string {
            if (text != "unlimited") return number(text);
            text = std::to_string(WF_UNLIMITED_DEPTH);
            return "";
        },
        "in 0 to " + std::to_string(hi) + ", or unlimited");
}

// Where a number's range starts.
enum class Lowest { Any, Zero, AboveZero };

// A finite number, at or above its lowest.
CLI::Validator finite_number(Lowest lowest) {
    return CLI::Validator(
        [lowest](std::string& text) -> std::string {
            std::istringstream in(text);
            double value = 0.0;
            if (!(in >> value) || !in.eof() || !std::isfinite(value)) return "'" + text + "' is not a number";
            if (lowest == Lowest::AboveZero && !(value > 0.0)) return text + " is not above 0";
            if (lowest == Lowest::Zero && !(value >= 0.0)) return text + " is below 0";
            return "";
        },
        lowest == Lowest::AboveZero ? "> 0" : lowest == Lowest::Zero ? ">= 0" : "");
}

// A number above lo and below hi, or up to it where `hi_included`.
CLI::Validator number_above(double lo, double hi, bool hi_included) {
    const std::string range = "(" + as_text(lo) + ", " + as_text(hi) + (hi_included ? "]" : ")");
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            std::istringstream in(text);
            double value = 0.0;
            if (!(in >> value) || !in.eof() || !std::isfinite(value)) return "'" + text + "' is not a number";
            if (!(value > lo && (hi_included ? value <= hi : value < hi))) return text + " is not in " + range;
            return "";
        },
        "in " + range);
}

// A probability above zero: a number in (0, 1].
CLI::Validator probability_above_zero() { return number_above(0.0, 1.0, true); }

// An angle of view in degrees: a number in (0, 180).
CLI::Validator field_of_view() { return number_above(0.0, 180.0, false); }

// The names of a choice (render_settings.h) as CLI11's list of allowed values.
std::vector<std::string> names_of(const ChoiceNames& names) {
    std::vector<std::string> list;
    for (const char* n : names)
        if (n) list.emplace_back(n);
    return list;
}

uint32_t index_of(const ChoiceNames& names, const std::string& name) {
    return choice_value(names, name).value_or(0); // IsMember has checked the name
}

// Help that ends with its default, the same words for every flag.
std::string with_default(const std::string& help, const std::string& value) {
    return help + " (default: " + value + ")";
}
template <class T> std::string with_default(const std::string& help, const T& value) {
    return with_default(help, as_text(value));
}

// The command's name and the flag, before CLI11's own words.
std::string parse_error_text(const CLI::App& app, const CLI::Error& e) {
    std::string prefix;
    for (const CLI::App* c = &app; !c->get_subcommands().empty();) {
        c = c->get_subcommands().back();
        prefix += (prefix.empty() ? "" : " ") + c->get_name();
    }
    std::string what = e.what();
    if (!what.empty() && what.back() == '\n') what.pop_back();
    for (char& c : what)
        if (c == '\n') c = ' ';
    if (what == "scene is required" || what == "scenes is required") what = "no scene file given";
    if (!what.empty()) what[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(what[0])));
    return prefix.empty() ? what : prefix + ": " + what;
}

// A word where a command belongs that names none: CLI11 would take it for an
// argument and ask for a command, without naming the word.
void check_command_word(const CLI::App& app, const std::string& word, const std::string& context) {
    if (word.empty() || word[0] == '-') return;
    std::string names;
    for (const CLI::App* c : app.get_subcommands({})) {
        if (c->get_name() == word) return;
        names += (names.empty() ? "" : ", ") + c->get_name();
    }
    throw InputError(context + "unknown command '" + word + "' (expected " + names + ")");
}

// --cache-dir, which render, cache warm and cache clear all take.
void add_cache_dir(CLI::App& command, std::string& directory) {
    command
        .add_option("--cache-dir", directory,
                    with_default("Where compiled kernels are kept", "$XDG_CACHE_HOME/wavefront, else ~/.cache/wavefront"))
        ->type_name("DIR");
}

// The render command's flags, each filling its field of `o`.
struct RenderFlags {
    std::string light_sampling, hemisphere, sampler, integrator, schedule, queue_push, kernels, config, look_at;
    std::vector<std::string> aovs;
    CLI::Option *schedule_flag = nullptr, *spp_flag = nullptr;
};

void declare_render(CLI::App& render, RenderOptions& o, RenderFlags& f) {
    RenderSettings& s = o.settings;
    // The last value given wins, so that a flag typed overrides --config's.
    render.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    render.add_option("scene", o.scene, "The glTF scene (.gltf or .glb)")->required()->type_name("SCENE");
    render.add_option("-o,--output", o.output, with_default("Output image; the extension picks the format", o.output))
        ->type_name("OUT");
    render.add_option("--exposure", o.exposure,
                      with_default("Scale an 8-bit output (.png, .jpg) by 2^EV before the sRGB curve; a float "
                                   "output keeps radiance", 0))
        ->check(finite_number(Lowest::Any))
        ->type_name("EV");
    render.add_flag("--half", o.half,
                    with_default("Store a float output's channels as 16-bit halves (a partial render stays "
                                 "32-bit)", "off"));
    f.spp_flag = render.add_option("--spp", s.spp, with_default("Samples per pixel", s.spp))
                     ->check(whole_number(1, 1u << 24));
    render.add_option("--width", o.width, with_default("Image width", std::to_string(kDefaultImageWidth) +
                                                                         ", or from --height and the camera's aspect"))
        ->check(whole_number(1, kMaxSide));
    render.add_option("--height", o.height, with_default("Image height", "from the width and the camera's aspect"))
        ->check(whole_number(1, kMaxSide));
    render.add_option("--max-depth", s.max_depth,
                      with_default("Bounces per path; 1 is direct lighting only, unlimited leaves it to roulette",
                                   s.max_depth == WF_UNLIMITED_DEPTH ? "unlimited" : as_text(s.max_depth)))
        ->transform(depth_limit(1u << 20));
    render.add_option("--roulette-depth", s.roulette_depth,
                      with_default("Bounces after which Russian roulette may end a path", s.roulette_depth))
        ->check(whole_number(1, 1u << 20));
    render.add_option("--roulette-cap", s.roulette_cap,
                      with_default("The largest probability with which roulette lets a path go on (Mitsuba: 0.95)",
                                   s.roulette_cap))
        ->check(probability_above_zero());
    render.add_option("--seed", s.seed, with_default("Random seed; the same seed and device give the same bytes", s.seed))
        ->check(whole_number(0, UINT32_MAX));
    render.add_option("--device", o.device,
                      with_default("OpenCL device: an index from `wavefront devices`, cpu or gpu; or several, "
                                   "comma-separated (0,2), or all, sharing the render unit by unit",
                                   "the first GPU, else the first device"));
    render.add_option("--pool-size", s.pool_size,
                      with_default("Paths in flight, at most the pixel count",
                                   std::to_string(kDefaultCpuPoolSize) + " for the wavefront on a CPU, where they " +
                                       "stay in cache, " + std::to_string(kDefaultPoolSize) +
                                       " for the megakernel there; on a GPU " +
                                       std::to_string(kGpuPathsPerComputeUnit) + " a compute unit, at least " +
                                       std::to_string(kDefaultPoolSize)))
        ->check(whole_number(1, 1u << 26));
    CLI::Option* camera = render.add_option("--camera", o.camera,
                                            with_default("Index of the glTF camera to use",
                                                         "the first perspective camera, else one framing the scene"))
                              ->check(whole_number(0, 1u << 20));
    render.add_option("--look-at", f.look_at,
                      with_default("A camera at EYE looking at TARGET, instead of the file's: EX,EY,EZ,TX,TY,TZ, "
                                   "and UX,UY,UZ for its up (else +y)", "none"))
        ->type_name("EYE,TARGET[,UP]")
        ->excludes(camera);
    render.add_option("--fov", o.fov,
                      with_default("The camera's vertical field of view, degrees", "the camera's own; 39.6 for "
                                   "one of --look-at or framing the scene"))
        ->check(field_of_view())
        ->type_name("DEGREES");
    f.integrator = integrator_name(s.integrator);
    render.add_option("--integrator", f.integrator,
                      with_default("wavefront (a kernel per stage, over queues) or megakernel (a kernel per path); "
                                   "the same image", f.integrator))
        ->check(CLI::IsMember(names_of(kIntegratorNames)));
    f.schedule = schedule_name(s.schedule);
    f.schedule_flag = render.add_option("--schedule", f.schedule,
                                        with_default("The wavefront's launch order: refill, passes (pbrt-v4), "
                                                     "fullest (Cycles X), group (every stage inside each "
                                                     "work-group, over local queues) or auto (group on a CPU, "
                                                     "refill elsewhere or with --sort-materials)", f.schedule))
                          ->check(CLI::IsMember(names_of(kScheduleNames)));
    render.add_flag("--sort-materials", s.sort_materials,
                    with_default("Sort the paths by the material they hit before shading, wavefront only", "off"));
    f.queue_push = queue_push_name(s.queue_push);
    render.add_option("--queue-push", f.queue_push,
                      with_default("How kernels append to queues: group (one atomic per work-group, the shares "
                                   "by local atomics), atomic (one per item), scan (prefix sum), serial (one "
                                   "item sums the group's shares) or auto (serial on a CPU's kernels, else group)",
                                   f.queue_push))
        ->check(CLI::IsMember(names_of(kQueuePushNames)));
    render.add_option("--local-size", s.local_size, with_default("Work-items per work-group", s.local_size))
        ->check(whole_number(16, 1024));
    render.add_option("--lane-width", s.lane_width,
                      with_default("Paths a work-item in the group schedule's BSDF lanes: 1, 8 or 16, or 0 for 8 "
                                   "on a CPU of 8-float vectors or wider (1 elsewhere); the same image", s.lane_width))
        ->check(CLI::IsMember({0u, 1u, 8u, 16u}));
    render.add_option("--trace-width", s.trace_width,
                      with_default("Rays a work-item traces at once: 1, 2, or 0 for 2 on a CPU where the scene's "
                                   "triangles outgrow the device's cache (1 elsewhere); the same image",
                                   s.trace_width))
        ->check(CLI::IsMember({0u, 1u, 2u}));
    render.add_option("--shade-kernels", s.shade_kernels,
                      with_default("Kernels the wavefront's shade stage runs as on refill, passes and fullest: 1, "
                                   "2 (surface, then the BSDF: fewer registers each), or 0 for 2 with a GPU's "
                                   "kernels (1 elsewhere); the same image",
                                   s.shade_kernels))
        ->check(CLI::IsMember({0u, 1u, 2u}));
    f.kernels = kernel_kind_name(s.kernels);
    render.add_option("--kernels", f.kernels,
                      with_default("Build the kernels for a cpu or a gpu, whatever the device, to test one kind's "
                                   "kernels on another; auto: for the device's kind; the same image", f.kernels))
        ->check(CLI::IsMember(names_of(kKernelKindNames)));
    render.add_option("--stats-json", o.stats_json,
                      with_default("Write the render's statistics as JSON: stage times, rays, counters per iteration",
                                   "none"))
        ->type_name("FILE");

    const std::string sampling = "Sampling techniques";
    f.light_sampling = choice_name(kLightSamplingNames, s.light_sampling);
    render.add_option("--light-sampling", f.light_sampling, with_default("How emitters are found", f.light_sampling))
        ->check(CLI::IsMember(names_of(kLightSamplingNames)))
        ->group(sampling);
    f.hemisphere = choice_name(kHemisphereNames, s.hemisphere);
    render.add_option("--hemisphere", f.hemisphere, with_default("Lambertian sampling", f.hemisphere))
        ->check(CLI::IsMember(names_of(kHemisphereNames)))
        ->group(sampling);
    f.sampler = choice_name(kSamplerNames, s.sampler);
    render.add_option("--sampler", f.sampler, with_default("Sample values (sobol: Owen-scrambled)", f.sampler))
        ->check(CLI::IsMember(names_of(kSamplerNames)))
        ->group(sampling);
    CLI::Option* env = render.add_option("--env", o.environment,
                                         with_default("Environment light: an equirectangular .exr or .hdr, "
                                                      "importance-sampled", "none; a scene without any light, or "
                                                      "lit by emissive textures alone, gets a uniform white one"))
                           ->type_name("FILE")
                           ->group(sampling);
    render.add_option("--env-uniform", o.environment_uniform,
                      with_default("Environment light of the same radiance L from every direction; 0: no "
                                   "environment, not even the white one an unlit scene gets", "none"))
        ->check(finite_number(Lowest::Zero))
        ->excludes(env)
        ->type_name("L")
        ->group(sampling);
    render.add_option("--env-rotate", o.environment_rotate, with_default("Turn --env about the up (+y) axis, degrees", 0))
        ->check(finite_number(Lowest::Any))
        ->needs(env)
        ->group(sampling);
    render.add_option("--env-scale", o.environment_scale, with_default("Multiply --env's radiance", 1))
        ->check(finite_number(Lowest::AboveZero))
        ->needs(env)
        ->group(sampling);
    add_cache_dir(render, o.cache_dir);
    render.add_option_function<std::string>(
              "--instancing",
              [&o](const std::string& name) { o.instancing = static_cast<Instancing>(index_of(kInstancingNames, name)); },
              with_default("Which meshes that several nodes place are kept once, under a tree of their "
                           "instances, the rest written out at each placement: all, large (those whose copies "
                           "beyond the first would hold " + std::to_string(kLargeSharedTriangles) +
                               " triangles or more; smaller ones render faster written out) or off",
                           kInstancingNames[static_cast<size_t>(o.instancing)]))
        ->check(CLI::IsMember(names_of(kInstancingNames)))
        ->type_name("MODE");
    render.add_flag_function("--no-specialize", [&s](int64_t) { s.specialize = false; },
                    with_default("Compile the generic kernels, every feature on, instead of those for the scene's "
                                 "features", "off"));
    render.add_option("--aov", f.aovs,
                      with_default("Extra EXR layers, comma-separated: albedo, normal, depth (the first hit's base "
                                   "colour, shading normal and distance, for a denoiser or compositor); bounces "
                                   "(the radiance after 0, 1, ..., 6 and 7+ reflections); samples (how many "
                                   "each pixel took, which --adaptive varies)",
                                   "none"))
        ->delimiter(',')
        ->check(CLI::IsMember({"albedo", "normal", "depth", "bounces", "samples"}));
    render.add_flag("--denoise", o.denoise,
                    with_default("Denoise the image with Intel Open Image Denoise 2.x (its RT filter, guided by the "
                                 "albedo and normal AOVs, which it turns on); an .exr keeps the noisy image as the "
                                 "layer noisy.R/G/B. Needs libOpenImageDenoise.so.2: scripts/setup.sh installs it, "
                                 "or set WF_OIDN_LIBRARY", "off"));

    const std::string error = "Error against time";
    render.add_option("--reference", o.reference,
                      with_default("Report MSE, relMSE and MAE against this image at every checkpoint (8-bit files "
                                   "are decoded from sRGB)", "none"))
        ->type_name("REF")
        ->group(error);
    render.add_option("--report", o.report_csv,
                      with_default("Write the checkpoints to this CSV file: seconds,spp,mse,relmse,mae,relmse_estimate",
                                   "none"))
        ->type_name("CSV")
        ->group(error);
    render.add_option("--report-every", o.progress.report_every,
                      with_default("A checkpoint every this many seconds", "at each doubling of spp"))
        ->check(finite_number(Lowest::AboveZero))
        ->type_name("SECONDS")
        ->group(error);
    render.add_option("--time", o.progress.time_budget,
                      with_default("Stop after this many seconds; then --spp, if given, is a cap", "none"))
        ->check(finite_number(Lowest::AboveZero))
        ->type_name("SECONDS")
        ->group(error);
    render.add_option("--target-error", o.progress.target_relmse,
                      with_default("Stop once the estimated relMSE is below X, checked from 16 spp on", "none"))
        ->check(finite_number(Lowest::AboveZero))
        ->type_name("X")
        ->group(error);
    render.add_flag("--adaptive", o.progress.adaptive,
                    with_default("Adaptive sampling toward --target-error: from 16 spp on, each pixel stops once it "
                                 "has the share of samples its variance (its 3x3 neighbourhood's) is worth, the "
                                 "square-root allocation that meets the target soonest; the render still ends on "
                                 "the image's error, or at --spp or --time",
                                 "off"))
        ->group(error);

    const std::string long_renders = "Long renders";
    render.add_option("--checkpoint-every", o.checkpoint_every,
                      with_default("Write the render so far to OUT.partial.exr this often, atomically (Ctrl-C "
                                   "writes it too)", "never"))
        ->check(finite_number(Lowest::AboveZero))
        ->type_name("SECONDS")
        ->group(long_renders);
    render.add_option("--resume", o.resume,
                      with_default("Go on from a partial render; the same scene contents, settings and seed are "
                                   "checked", "none"))
        ->type_name("PARTIAL")
        ->group(long_renders);
    render.add_flag("--quiet", o.quiet, with_default("Print errors only: no progress, table, report or warning", "off"))
        ->group(long_renders);
    render.add_option("--config", f.config,
                      with_default("Read flags from a TOML file (spp = 64, env-uniform = 1.0, quiet = true, ...); "
                                   "flags on the command line win", "none"))
        ->type_name("FILE");
}

// --look-at's six or nine finite numbers: eye, target and up (+y when left out).
std::array<float, 9> look_at_numbers(const std::string& text) {
    std::array<float, 9> v{0, 0, 0, 0, 0, 0, 0, 1, 0};
    std::istringstream in(text);
    std::string word;
    size_t n = 0;
    for (; std::getline(in, word, ','); ++n) {
        char* end = nullptr;
        const float x = n < 9 ? std::strtof(word.c_str(), &end) : 0.0f;
        if (n >= 9 || word.empty() || *end != '\0' || !std::isfinite(x))
            throw InputError("render: --look-at " + text + ": expected six or nine finite numbers, comma-separated "
                             "(EX,EY,EZ,TX,TY,TZ[,UX,UY,UZ])");
        v[n] = x;
    }
    if (n != 6 && n != 9)
        throw InputError("render: --look-at " + text + ": expected six or nine numbers, not " + std::to_string(n));
    return v;
}

// After parsing: the choices into settings, and the checks between flags.
void settle_render(RenderOptions& o, const RenderFlags& f) {
    RenderSettings& s = o.settings;
    if (!f.look_at.empty()) o.look_at = look_at_numbers(f.look_at);
    s.integrator = static_cast<Integrator>(index_of(kIntegratorNames, f.integrator));
    s.schedule = static_cast<Schedule>(index_of(kScheduleNames, f.schedule));
    s.queue_push = static_cast<QueuePush>(index_of(kQueuePushNames, f.queue_push));
    s.kernels = static_cast<KernelKind>(index_of(kKernelKindNames, f.kernels));
    s.light_sampling = index_of(kLightSamplingNames, f.light_sampling);
    s.hemisphere = index_of(kHemisphereNames, f.hemisphere);
    s.sampler = index_of(kSamplerNames, f.sampler);
    for (const std::string& aov : f.aovs) {
        if (aov == "bounces") s.bounce_layers = 8;
        for (const auto& [name, bit] : kAovBits)
            if (aov == name) s.aovs |= bit;
    }
    o.aovs_asked = s.aovs;
    if (o.denoise) s.aovs |= WF_AOV_ALBEDO | WF_AOV_NORMAL; // the denoiser's guides
    if (std::abs(o.exposure) > 64.0f) // 2^64 already turns any radiance white or black
        throw InputError("render: --exposure: " + as_text(o.exposure) + " is not in -64 to 64");
    if (o.exposure != 0.0f && holds_float_radiance(o.output))
        throw InputError("render: --exposure " + as_text(o.exposure) + ": " + o.output +
                         " keeps linear radiance; exposure applies to 8-bit outputs such as .png");
    if (o.half && !holds_float_radiance(o.output))
        throw InputError("render: --half: " + o.output + " is not a float format such as .exr");
    if (s.integrator == Integrator::Megakernel && f.schedule_flag->count())
        throw InputError("render: --schedule orders the wavefront's stages; the megakernel has none");
    if (s.integrator == Integrator::Megakernel && s.sort_materials)
        throw InputError("render: --sort-materials sorts the wavefront's queue; the megakernel has none");
    if (s.schedule == Schedule::Group && s.sort_materials)
        throw InputError("render: --sort-materials sorts the wavefront's global queue; --schedule group has none");
    if (o.progress.adaptive && o.progress.target_relmse <= 0.0)
        throw InputError("render: --adaptive shares the samples out toward --target-error; give one");
    // A time budget or a target error alone leaves the sample count open.
    const bool open_ended = o.progress.time_budget > 0.0 || o.progress.target_relmse > 0.0;
    if (!f.spp_flag->count() && open_ended) s.spp = 0;
}

void declare_cache(CLI::App& cache, CommandLine& cl) {
    cache.require_subcommand(1);
    CLI::App* warm = cache.add_subcommand("warm", "Compile the kernels these scenes need ahead of time");
    warm->add_option("scenes", cl.cache.scenes, "glTF scenes")->required()->type_name("SCENE...");
    warm->add_option("--device", cl.cache.device,
                     with_default("OpenCL device: an index, cpu or gpu", "the first GPU, else the first device"));
    add_cache_dir(*warm, cl.cache.directory);
    warm->callback([&cl] { cl.command = Command::CacheWarm; });
    CLI::App* clear = cache.add_subcommand("clear", "Remove the compiled kernels kept on disk");
    add_cache_dir(*clear, cl.cache.directory);
    clear->callback([&cl] { cl.command = Command::CacheClear; });
}

// The whole command line, filling `cl` and `flags`; returns the render command.
CLI::App& declare_app(CLI::App& app, CommandLine& cl, RenderFlags& flags) {
    app.require_subcommand(1);
    app.add_flag("--version", "Print the commit, build type and the OpenCL, PoCL and OpenImageIO versions");
    CLI::App* render = app.add_subcommand("render", "Render a glTF scene and write the image (.exr: linear float "
                                                    "radiance; .png and other 8-bit formats: sRGB)");
    declare_render(*render, cl.render, flags);
    render->callback([&cl] { cl.command = Command::Render; });
    app.add_subcommand("devices", "List OpenCL platforms and devices")->callback([&cl] { cl.command = Command::Devices; });
    declare_cache(*app.add_subcommand("cache", "Compiled kernels on disk: warm SCENE... or clear"), cl);
    return *render;
}

// Each value a --config file gives passes its flag's check alone, so that a
// bad one is named with the file and line it came from (config_file.h).
void check_config_values(const std::string& path, const std::vector<ConfigFlag>& from_file) {
    CommandLine scratch;
    RenderFlags scratch_flags;
    CLI::App app;
    declare_app(app, scratch, scratch_flags);
    std::vector<std::string> words{"render", "scene.gltf"};
    for (const ConfigFlag& f : from_file) words.push_back(f.argument);
    std::reverse(words.begin(), words.end()); // CLI11 takes them last first
    try {
        app.parse(words);
    } catch (const CLI::ParseError& e) {
        throw InputError(config_error(path, from_file, parse_error_text(app, e)));
    }
}

} // namespace

std::vector<FlagInfo> render_flags() {
    CommandLine cl;
    RenderFlags flags;
    CLI::App app;
    const CLI::App& render = declare_app(app, cl, flags);
    std::vector<FlagInfo> list;
    for (const CLI::Option* o : render.get_options()) {
        if (o->get_lnames().empty() || o->get_lnames()[0] == "help") continue; // the scene; --help
        list.push_back({o->get_lnames()[0], o->get_type_name(), o->get_description(), o->get_expected_min() != 0});
    }
    return list;
}

CommandLine parse_command_line(int argc, const char** argv) {
    CommandLine cl;
    CLI::App app("Renders glTF scenes by wavefront path tracing on OpenCL devices.", "wavefront");
    RenderFlags flags;
    CLI::App* render = &declare_app(app, cl, flags);

    // --version alone, before CLI11 asks for a command.
    if (argc == 2 && std::string(argv[1]) == "--version") {
        cl.command = Command::Version;
        return cl;
    }
    if (argc > 1) check_command_word(app, argv[1], "");
    if (argc > 2 && std::string(argv[1]) == "cache") check_command_word(*app.get_subcommand("cache"), argv[2], "cache: ");
    std::vector<std::string> words(argv + 1, argv + argc); // CLI11 takes them last first
    if (argc > 1 && std::string(argv[1]) == "render")
        if (const std::string config = config_path(argc, argv); !config.empty()) {
            const std::vector<ConfigFlag> from_file = read_config_flags(*render, config);
            check_config_values(config, from_file);
            for (size_t i = 0; i < from_file.size(); ++i) words.insert(words.begin() + 1 + i, from_file[i].argument);
        }
    std::reverse(words.begin(), words.end());
    try {
        app.parse(words);
    } catch (const CLI::CallForHelp&) {
        cl.command = Command::Help;
        cl.help = app.help(); // the help of the command asked about, when one was
        return cl;
    } catch (const CLI::CallForAllHelp&) {
        cl.command = Command::Help;
        cl.help = app.help("", CLI::AppFormatMode::All);
        return cl;
    } catch (const CLI::ParseError& e) {
        if (argc < 2) { // no command: the help, as most tools do
            cl.command = Command::Help;
            cl.help = app.help();
            return cl;
        }
        throw InputError(parse_error_text(app, e));
    }
    if (cl.command == Command::Render) settle_render(cl.render, flags);
    return cl;
}

} // namespace wf
