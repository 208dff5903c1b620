// rank_zero.h — on rank 0, the other ranks: their setups gathered and checked
// against this render, their devices made workers of the Renderer
// (remote_device.h), and, however the render ends, every device told that the
// work is over, so that no rank waits for ever.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "cluster/unit_messages.h"
#include "render/unit_worker.h"
#include "scene/camera.h"

namespace wf {

class OtherRanks {
public:
    explicit OtherRanks(int ranks) : ranks_(ranks) {}
    // Receives any setup not yet received, then ends every device's work.
    ~OtherRanks();
    OtherRanks(const OtherRanks&) = delete;
    OtherRanks& operator=(const OtherRanks&) = delete;

    // Every other rank's devices, once each rank is ready. Throws the first
    // failed set-up as that rank's error (InputError for its input), or
    // InputError naming a rank whose scene or image is not this one's.
    std::vector<std::unique_ptr<UnitWorker>> join(const std::string& scene_contents, ImageSize size,
                                                  const std::atomic<int>* stop);


private:
    void receive_setups();
    int ranks_;
    std::vector<RankSetup> setups_; // by rank; rank 0's is empty
};

} // namespace wf
