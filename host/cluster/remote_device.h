// remote_device.h — on rank 0, a device of another rank as one more worker
// of the Renderer (render/unit_worker.h): each unit is a request and a reply
// (unit_messages.h), from the thread the Renderer gives this worker.
#pragma once

#include <atomic>

#include "cluster/unit_messages.h"
#include "render/unit_worker.h"

namespace wf {

class RemoteDevice : public UnitWorker {
public:
    // Device `index` of `rank`, as the rank's setup named it; `stop` is this
    // rank's stop flag.
    RemoteDevice(int rank, int index, std::string name, uint32_t pool, const std::atomic<int>* stop);

    void render_unit(uint32_t first, uint32_t count, uint32_t round_spp, FilmState& image, bool held) override;
    std::string name() const override { return "rank " + std::to_string(rank_) + ": " + name_; }
    uint32_t most_pixels() const override { return pool_; }
    RenderStats counts() const override { return counts_; }
    // Moving sums both ways: the messages and the device's own transfers there.
    double transfer_seconds() const override { return message_seconds_ + remote_transfer_seconds_; }

    // How long a stopped render waits for a unit in flight on another rank.
    static constexpr int kStoppedWaitMs = 300;


private:
    int rank_, index_;
    std::string name_;
    uint32_t pool_;
    const std::atomic<int>* stop_;
    RenderStats counts_;
    double message_seconds_ = 0.0, remote_transfer_seconds_ = 0.0;
};

} // namespace wf
