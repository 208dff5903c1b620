// run_render.cpp — everything that can be rejected (the scene, the
// reference, the output format, a partial render to resume) is rejected
// before rendering; Ctrl-C writes what the render has, and a partial render
// to go on from.
#include "session/run_render.h"

#include <chrono>
#include <filesystem>
#include <ostream>

#include <unistd.h>

#include "base/errors.h"
#include "base/output_files.h"
#include "film/partial_render.h"
#include "gltf/gltf_loader.h"
#include "image/denoiser.h"
#include "image/image_io.h"
#include "render/progressive_render.h"
#include "render/render_stats_json.h"
#include "render/renderer.h"
#include "session/checkpoint_log.h"
#include "session/image_options.h"
#include "session/interrupt.h"
#include "session/kernel_cache.h"
#include "session/progress_line.h"
#include "session/render_scene.h"

namespace wf {
namespace {

// Every file the render may write, checked before any work starts: the
// image, the partial render that Ctrl-C or --checkpoint-every writes beside
// it, the CSV report and the statistics.
void check_outputs(const RenderOptions& o, bool image) {
    if (image) {
        check_can_write(o.output);
        check_can_write_file(partial_render_path(o.output));
    }
    if (!o.report_csv.empty()) check_can_write_file(o.report_csv);
    if (!o.stats_json.empty()) check_can_write_file(o.stats_json);
}

// The --aov layers the film holds, as the image file names them.
std::vector<ImageLayer> aov_layers(const FilmReadout& film) {
    std::vector<ImageLayer> layers;
    if (film.albedo) layers.push_back({"albedo", *film.albedo});
    if (film.normal) layers.push_back({"normal", *film.normal, {"X", "Y", "Z"}});
    if (film.depth) layers.push_back({"depth", *film.depth, {"Z"}});
    if (film.samples) layers.push_back({"samples", *film.samples, {"Y"}});
    for (size_t i = 0; i < film.bounce_layers.size(); ++i)
        layers.push_back({bounce_layer_name(i, film.bounce_layers.size()), film.bounce_layers[i]});
    return layers;
}

} // namespace

RenderSettings device_settings(const RenderOptions& options, const std::atomic<int>* stop) {
    RenderSettings settings = options.settings; // with --denoise's guides among its AOVs (cli.cpp)
    settings.cache_dir = cache_directory(options.cache_dir);
    settings.stop = stop;
    return settings;
}

RenderSummary run_render(const RenderOptions& options, std::ostream& out, std::ostream& log,
                         const RenderHooks& hooks) {
    const auto start = std::chrono::steady_clock::now();
    // Before anything is read or written: a render that cannot be denoised is not begun.
    if (options.denoise) denoiser_library();
    check_outputs(options, hooks.write_image);
    Scene scene = hooks.scene ? *hooks.scene : load_gltf(options.scene, LoadOptions{options.camera, options.instancing});
    ready_for_render(scene, options, log);
    const double load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const std::string& w : scene.warnings) log << "warning: " << options.scene << ": " << w << "\n";
    if (!scene.camera) log << "note: " << options.scene << " has no camera; framing its bounds\n";

    const ImageSize size = resolve_image_size(options.width, options.height, scene.camera);
    // The layers asked for; --denoise's albedo and normal go to a float output only.
    const bool layers =
        options.settings.bounce_layers || (options.denoise ? options.aovs_asked : options.settings.aovs);
    if (layers && (options.checkpoint_every > 0.0 || !options.resume.empty()))
        throw InputError("--aov layers cannot be checkpointed or resumed (a partial render keeps the image alone)");
    if (options.denoise && (options.checkpoint_every > 0.0 || !options.resume.empty()))
        throw InputError("--denoise cannot be checkpointed or resumed (a partial render keeps the image alone, "
                         "not the albedo and normal it needs)");
    // Checked before the long set-up.
    const ImageOptions shaping = image_options(options, size);
    std::optional<PartialRender> resumed;
    if (!options.resume.empty()) {
        resumed = read_partial_render(options.resume);
        check_partial_options(*resumed, options.resume, resume_checks(shaping));
        const uint32_t held = resolve(resumed->film).min_samples;
        if (options.settings.spp && options.settings.spp <= held)
            throw InputError("--spp " + std::to_string(options.settings.spp) + ": " + options.resume +
                             " already holds " + std::to_string(held) + " spp; ask for more to go on");
    }
    if (layers && hooks.write_image && !holds_float_radiance(options.output))
        throw InputError(options.output + ": --aov layers need a float format such as .exr");
    std::optional<Image> reference;
    if (hooks.reference) reference = *hooks.reference;
    const std::string reference_name = hooks.reference ? std::string("the reference") : options.reference;
    if (!reference && !options.reference.empty()) {
        reference = read_image(options.reference);
        if (reference->stored.levels > 0) {
            // Assumed written as this command would write an 8-bit image.
            reference->stored.exposure = options.exposure;
            log << "note: " << options.reference << " holds " << reference->stored.levels + 1
                << " levels a channel: the render is compared with it clipped to [0, 1] and quantised as it is\n";
        }
    }
    if (reference && (reference->width != size.width || reference->height != size.height))
        throw InputError(reference_name + ": the reference is " + std::to_string(reference->width) + "x" +
                         std::to_string(reference->height) + " but the render is " + std::to_string(size.width) + "x" +
                         std::to_string(size.height));

    const std::vector<OpenClDevice> devices = open_devices(options.device);
    std::vector<const OpenClDevice*> chosen;
    for (const OpenClDevice& d : devices) chosen.push_back(&d);
    const std::atomic<int>* stop = hooks.stop ? hooks.stop : &install_interrupt_handlers();
    const RenderSettings settings = device_settings(options, stop);
    // Compiling takes seconds on a cold cache: say so on a terminal, then erase the line.
    const bool terminal = ::isatty(STDERR_FILENO);
    if (terminal && !options.quiet)
        log << "building the render: BVH, kernels (cache " << settings.cache_dir << ")..." << std::flush;
    Renderer renderer(chosen, scene, scene.camera ? *scene.camera : frame_bounds(scene.bounds()), size, settings);
    if (terminal && !options.quiet) log << "\r\33[K" << std::flush;
    if (!renderer.summary().pool_note.empty()) log << "note: " << renderer.summary().pool_note << "\n";
    if (!renderer.summary().build_warning.empty()) log << "warning: " << renderer.summary().build_warning << "\n";
    if (hooks.add_workers) hooks.add_workers(renderer, size);
    ProgressOptions progress = options.progress;
    progress.reference = reference ? &*reference : nullptr;
    progress.stop = settings.stop;
    if (resumed) progress.start_spp = renderer.resume(resumed->film);
    if (options.checkpoint_every > 0.0 && progress.report_every == 0.0) progress.report_every = options.checkpoint_every;

    ImageMetadata metadata;
    for (const OpenClDevice& d : devices)
        metadata.device += (metadata.device.empty() ? "" : ", ") + d.info.name;
    metadata.seed = options.settings.seed;
    metadata.scene = canonical_path(options.scene);
    metadata.options = shaping;
    ProgressLine progress_line(log, terminal, terminal ? 0.25 : 10.0, uint64_t{size.width} * size.height,
                               options.settings.spp, progress);
    renderer.on_progress([&](const RenderStats& s) {
        if (!options.quiet) progress_line.update(s);
        if (hooks.on_progress) hooks.on_progress(s);
    });
    const std::string partial_path = partial_render_path(options.output);
    bool partial_written = false;
    auto write_partial = [&] {
        if (!hooks.write_image) return;
        metadata.samples_per_pixel = renderer.read().min_samples;
        metadata.render_seconds = renderer.stats().seconds;
        write_partial_render(partial_path, renderer.film_state(), metadata);
        partial_written = true;
    };
    auto last_checkpoint = std::chrono::steady_clock::now();
    CheckpointLog checkpoints(out, options.report_csv);
    const FilmReadout film = render_progressively(renderer, options.settings.spp, progress, [&](const Checkpoint& c) {
        progress_line.clear(); // stdout and stderr may share the terminal
        checkpoints.add(c);
        if (hooks.on_checkpoint) hooks.on_checkpoint(c);
        if (c.relmse_estimate) progress_line.set_error(*c.relmse_estimate);
        const auto now = std::chrono::steady_clock::now();
        if (options.checkpoint_every > 0.0 &&
            std::chrono::duration<double>(now - last_checkpoint).count() >= options.checkpoint_every) {
            write_partial();
            last_checkpoint = now;
        }
    });
    progress_line.clear();

    RenderSummary summary = renderer.summary();
    summary.ranks = options.ranks;
    if (options.ranks > 1) // the other ranks' devices are named by their rank already
        for (DeviceShare& share : summary.shares)
            if (share.device.rfind("rank ", 0) != 0) share.device = "rank 0: " + share.device;
    summary.interrupted_by = stop->load();
    summary.spp = film.min_samples;
    summary.most_spp = film.max_samples;
    summary.mean_spp = film.mean_samples;
    summary.resumed_from_spp = progress.start_spp;
    // The denoised image, of whatever samples finished (none: nothing to denoise).
    std::optional<Image> denoised;
    if (options.denoise && summary.stats.samples > 0) {
        const auto denoise_start = std::chrono::steady_clock::now();
        denoised = denoise(film.mean, *film.albedo, *film.normal);
        summary.times.denoise =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - denoise_start).count();
        if (!options.quiet) log << "note: denoised by Open Image Denoise (" << denoiser_library() << ")\n";
    }
    if (hooks.write_image) {
        metadata.samples_per_pixel = film.min_samples;
        metadata.render_seconds = summary.stats.seconds;
        metadata.interrupted = summary.interrupted_by != 0;
        // Stopped before a sample finished: what is on disk (an older image, the
        // partial it resumed from) is worth more than nothing, so nothing is written.
        const bool computed = summary.stats.samples > 0;
        if (summary.interrupted_by && !computed)
            log << "interrupted before any sample finished: nothing written\n";
        else if (denoised) {
            // The noisy image stays beside the denoised one where the format holds layers.
            std::vector<ImageLayer> kept;
            if (holds_float_radiance(options.output)) {
                kept = aov_layers(film);
                kept.insert(kept.begin(), ImageLayer{"noisy", film.mean});
            }
            ImageMetadata denoised_metadata = metadata;
            denoised_metadata.options = with_denoiser(metadata.options);
            write_image(options.output, *denoised, denoised_metadata, kept,
                        ImageEncoding{options.half, options.exposure});
        } else
            write_image(options.output, film.mean, metadata, aov_layers(film),
                        ImageEncoding{options.half, options.exposure});
        std::error_code ignored;
        if (summary.interrupted_by && computed) {
            write_partial();
            log << "interrupted: wrote " << options.output << " (" << film.min_samples << "+ spp) and "
                << partial_path << "; go on with --resume " << partial_path
                << (options.denoise ? " (without --denoise: the partial keeps the image alone)" : "") << "\n";
        } else if (!summary.interrupted_by) {
            // The image is whole: the partial it was checkpointed to, or resumed from, is stale.
            if (partial_written || (resumed && std::filesystem::equivalent(options.resume, partial_path, ignored)))
                std::filesystem::remove(partial_path, ignored);
        }
    }

    summary.scene = options.scene;
    if (hooks.write_image) summary.output = options.output;
    summary.times.load = load_seconds;
    if (!options.stats_json.empty()) write_stats_json(options.stats_json, summary);
    if (hooks.film) *hooks.film = film;
    if (hooks.denoised && denoised) *hooks.denoised = std::move(*denoised);
    return summary;
}

} // namespace wf
