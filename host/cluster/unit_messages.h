// unit_messages.h — what rank 0 and the devices of other ranks say to each
// other. Each remote device has a tag, its index on its rank, and one
// conversation with rank 0 at a time: a request (a unit, with the unit's sums
// unless the device holds them, or the end of the work), then a reply (the
// device's counts and the unit's sums). Before that, each rank sends rank 0
// its setup under kSetupTag. Every rank runs the same build on the same kind
// of machine, so plain structs travel as bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "integrator/path_integrator.h"

namespace wf {

constexpr int kSetupTag = 1 << 14; // above any device index

enum class UnitCommand : uint32_t { Render = 1, End = 2 };

struct UnitRequest {
    UnitCommand command = UnitCommand::End;
    uint32_t first = 0, count = 0, round_spp = 0;
    uint32_t held = 0; // 1: the device's film has the unit's sums, none follow
};

// What a reply starts with: 0, then the counts and the unit's sums; or the
// exit status of the unit's failure, then its message.
struct UnitReplyStatus {
    uint32_t failure = 0;
};

// A device's counts so far as they travel, with the time its last unit took there.
struct UnitCounts {
    uint64_t samples, closest_rays, shadow_rays, nonfinite_samples, lane_paths, lane_slots, iterations, pool_bytes;
    uint32_t pool_size, pad;
    double seconds, transfer_seconds, unit_seconds;
    double stage_seconds[STAGE_COUNT];
    uint64_t stage_launches[STAGE_COUNT];
    uint64_t path_lengths[WF_PATH_LENGTH_BUCKETS];
};

UnitCounts to_wire(const RenderStats& counts, double transfer_seconds, double unit_seconds);
RenderStats from_wire(const UnitCounts& wire);

// What a rank other than 0 tells rank 0 once it is ready, or why it is not.
struct RankSetup {
    std::string error; // empty: ready
    std::string scene_contents; // its scene file's fingerprint
    uint32_t width = 0, height = 0;
    std::vector<std::pair<std::string, uint32_t>> devices; // name, pool
};

std::string encode_setup(const RankSetup& setup);
RankSetup decode_setup(const std::string& text);

// Blocking point-to-point messages on MPI_COMM_WORLD; `what` names the
// exchange in the error when MPI fails.
void send_bytes(const void* data, size_t size, int rank, int tag, const std::string& what);
// A whole message of any size from `rank` under `tag`.
std::vector<unsigned char> receive_bytes(int rank, int tag, const std::string& what);
// The same, unless `give_up` says to stop waiting (checked every millisecond
// or so while none has arrived): then nothing.
std::optional<std::vector<unsigned char>> receive_bytes_unless(int rank, int tag, const std::string& what,
                                                               const std::function<bool()>& give_up);

} // namespace wf
