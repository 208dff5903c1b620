// worker_rank.cpp — the rank keeps an image of its own, of which each device
// reads and writes only its units' pixels, so the threads share nothing else.
#include "cluster/worker_rank.h"

#include <chrono>
#include <cstring>
#include <memory>
#include <ostream>
#include <thread>

#include "base/file_fingerprint.h"
#include "cluster/unit_messages.h"
#include "render/device_renderer.h"
#include "session/exit_status.h"
#include "session/interrupt.h"
#include "session/render_scene.h"
#include "session/run_render.h"

namespace wf {
namespace {

// The reply to a unit: its counts and sums.
std::vector<unsigned char> unit_reply(DeviceRenderer& device, const UnitRequest& request, const unsigned char* sums,
                                      size_t sums_size, FilmState& image) {
    const auto start = std::chrono::steady_clock::now();
    if (!request.held) unpack_pixels(sums, sums_size, request.first, request.count, image);
    device.render_unit(request.first, request.count, request.round_spp, image, request.held != 0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const UnitCounts counts = to_wire(device.counts(), device.transfer_seconds(), seconds);
    std::vector<unsigned char> reply(sizeof(UnitReplyStatus) + sizeof counts);
    std::memcpy(reply.data() + sizeof(UnitReplyStatus), &counts, sizeof counts);
    const std::vector<unsigned char> packed = pack_pixels(image, request.first, request.count);
    reply.insert(reply.end(), packed.begin(), packed.end());
    return reply;
}

// One device's conversation with rank 0, until the end of the work. A unit
// that fails is answered with its failure, so rank 0 never waits in vain.
void serve_device(DeviceRenderer& device, int index, FilmState& image) {
    const std::string what = "rank 0's request to " + device.name();
    for (;;) {
        const std::vector<unsigned char> message = receive_bytes(0, index, what);
        UnitRequest request;
        if (message.size() < sizeof request) throw std::runtime_error(what + ": a short request");
        std::memcpy(&request, message.data(), sizeof request);
        if (request.command == UnitCommand::End) return;
        std::vector<unsigned char> reply;
        try {
            reply = unit_reply(device, request, message.data() + sizeof request, message.size() - sizeof request,
                               image);
        } catch (...) {
            const Failure failure = describe_exception();
            const UnitReplyStatus status{static_cast<uint32_t>(failure.exit_code)};
            reply.resize(sizeof status);
            std::memcpy(reply.data(), &status, sizeof status);
            reply.insert(reply.end(), failure.message.begin(), failure.message.end());
        }
        send_bytes(reply.data(), reply.size(), 0, index, device.name() + "'s reply to rank 0");
    }
}

} // namespace

int serve_units(const RenderOptions& options) {
    RankSetup setup;
    std::vector<OpenClDevice> devices;
    std::vector<std::unique_ptr<DeviceRenderer>> renderers;
    FilmState image;
    try {
        std::ostream quiet(nullptr);
        const Scene scene = load_render_scene(options, quiet);
        const ImageSize size = resolve_image_size(options.width, options.height, scene.camera);
        devices = open_devices(options.device);
        const RenderSettings settings = device_settings(options, &install_interrupt_handlers());
        std::vector<const OpenClDevice*> chosen;
        for (const OpenClDevice& d : devices) chosen.push_back(&d);
        std::optional<Scene> flat;
        const Scene& rendered = scene_for_devices(scene, chosen, settings, flat);
        const SceneBuild build(rendered);
        const SceneCamera camera = scene.camera ? *scene.camera : frame_bounds(scene.bounds());
        for (const OpenClDevice& d : devices)
            renderers.push_back(std::make_unique<DeviceRenderer>(d, rendered, build, camera, size, settings));
        image = renderers[0]->film_state(); // zeroes, as every device's film is
        setup.scene_contents = file_fingerprint(options.scene);
        setup.width = size.width;
        setup.height = size.height;
        for (const auto& r : renderers) setup.devices.emplace_back(r->name(), r->most_pixels());
    } catch (...) {
        const Failure failure = describe_exception();
        setup.error = std::to_string(failure.exit_code) + " " + failure.message;
    }
    const std::string text = encode_setup(setup);
    send_bytes(text.data(), text.size(), 0, kSetupTag, "this rank's setup");
    if (!setup.error.empty()) return 0;

    std::vector<std::thread> threads;
    std::vector<std::exception_ptr> errors(renderers.size());
    for (size_t d = 0; d < renderers.size(); ++d)
        threads.emplace_back([&, d] {
            try {
                serve_device(*renderers[d], static_cast<int>(d), image);
            } catch (...) {
                errors[d] = std::current_exception();
            }
        });
    for (std::thread& t : threads) t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
    return interrupt_signal() ? 128 + interrupt_signal() : 0;
}

} // namespace wf
