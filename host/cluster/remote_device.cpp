// remote_device.cpp — the time a unit spends outside the remote device's
// own unit is the messages' time.
#include "cluster/remote_device.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "base/errors.h"

namespace wf {

RemoteDevice::RemoteDevice(int rank, int index, std::string name, uint32_t pool, const std::atomic<int>* stop)
    : rank_(rank), index_(index), name_(std::move(name)), pool_(pool), stop_(stop) {}

void RemoteDevice::render_unit(uint32_t first, uint32_t count, uint32_t round_spp, FilmState& image, bool held) {
    const auto start = std::chrono::steady_clock::now();
    const std::string what = "a unit of work for " + name();
    const UnitRequest request{UnitCommand::Render, first, count, round_spp, held ? 1u : 0u};
    std::vector<unsigned char> message(sizeof request);
    std::memcpy(message.data(), &request, sizeof request);
    if (!held) {
        const std::vector<unsigned char> sums = pack_pixels(image, first, count);
        message.insert(message.end(), sums.begin(), sums.end());
    }
    send_bytes(message.data(), message.size(), rank_, index_, what);

    // Stopped (Ctrl-C: mpirun ends every rank a second after its signal),
    // this rank waits a moment for the unit, then writes what it has without
    // it: the unit's pixels keep their sums from before it.
    std::optional<std::chrono::steady_clock::time_point> stop_seen;
    const std::optional<std::vector<unsigned char>> received = receive_bytes_unless(rank_, index_, what, [&] {
        if (!stop_requested(stop_)) return false;
        if (!stop_seen) stop_seen = std::chrono::steady_clock::now();
        return std::chrono::steady_clock::now() - *stop_seen > std::chrono::milliseconds(kStoppedWaitMs);
    });
    if (!received) return;
    const std::vector<unsigned char>& reply = *received;
    UnitReplyStatus status;
    UnitCounts wire{};
    if (reply.size() < sizeof status) throw std::runtime_error(what + ": a short reply");
    std::memcpy(&status, reply.data(), sizeof status);
    if (status.failure) {
        const std::string message = name() + ": " + std::string(reply.begin() + sizeof status, reply.end());
        if (status.failure == 2) throw InputError(message);
        throw std::runtime_error(message);
    }
    if (reply.size() < sizeof status + sizeof wire) throw std::runtime_error(what + ": a short reply");
    std::memcpy(&wire, reply.data() + sizeof status, sizeof wire);
    const size_t at = sizeof status + sizeof wire;
    unpack_pixels(reply.data() + at, reply.size() - at, first, count, image);
    // A unit comes back short only when its rank was stopped: with this one,
    // by mpirun's signal to every rank, which may reach this rank a moment
    // later; alone, it is a failure of that rank.
    const bool short_unit = std::any_of(image.samples.begin() + first, image.samples.begin() + first + count,
                                        [&](uint32_t n) { return n < round_spp; });
    for (int wait = 0; short_unit && !stop_requested(stop_) && wait < 500; ++wait)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (short_unit && !stop_requested(stop_))
        throw std::runtime_error(name() + " stopped before its unit was done, and this rank was not (was it signalled alone?)");
    counts_ = from_wire(wire);
    remote_transfer_seconds_ = wire.transfer_seconds;
    message_seconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - wire.unit_seconds;
}

} // namespace wf
