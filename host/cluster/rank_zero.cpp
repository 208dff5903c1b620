// rank_zero.cpp — setups arrive by rank, in order; each failure is named by its rank.
#include "cluster/rank_zero.h"

#include <cstring>
#include <stdexcept>

#include "base/errors.h"
#include "cluster/remote_device.h"

namespace wf {

void OtherRanks::receive_setups() {
    if (!setups_.empty()) return;
    setups_.resize(ranks_);
    for (int rank = 1; rank < ranks_; ++rank) {
        const std::vector<unsigned char> bytes = receive_bytes(rank, kSetupTag, "rank " + std::to_string(rank) + "'s setup");
        setups_[rank] = decode_setup(std::string(bytes.begin(), bytes.end()));
    }
}

std::vector<std::unique_ptr<UnitWorker>> OtherRanks::join(const std::string& scene_contents, ImageSize size,
                                                          const std::atomic<int>* stop) {
    receive_setups();
    std::vector<std::unique_ptr<UnitWorker>> workers;
    for (int rank = 1; rank < ranks_; ++rank) {
        const RankSetup& s = setups_[rank];
        const std::string who = "rank " + std::to_string(rank);
        if (!s.error.empty()) {
            // "<exit status> <message>", as worker_rank.cpp sends it.
            const std::string message = who + ": " + s.error.substr(s.error.find(' ') + 1);
            if (s.error.rfind("2 ", 0) == 0) throw InputError(message);
            throw std::runtime_error(message);
        }
        if (s.scene_contents != scene_contents)
            throw InputError(who + " read another scene (the file's contents differ from rank 0's)");
        if (s.width != size.width || s.height != size.height)
            throw InputError(who + " renders " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                             ", not rank 0's " + std::to_string(size.width) + "x" + std::to_string(size.height));
        for (size_t d = 0; d < s.devices.size(); ++d)
            workers.push_back(std::make_unique<RemoteDevice>(rank, static_cast<int>(d), s.devices[d].first,
                                                             s.devices[d].second, stop));
    }
    return workers;
}

OtherRanks::~OtherRanks() {
    try {
        receive_setups();
        const UnitRequest end{UnitCommand::End, 0, 0, 0, 0};
        for (int rank = 1; rank < ranks_; ++rank)
            for (size_t d = 0; d < setups_[rank].devices.size(); ++d)
                send_bytes(&end, sizeof end, rank, static_cast<int>(d), "the end of rank " + std::to_string(rank) + "'s work");
    } catch (...) {
        // MPI failed under us: mpirun ends every rank when one fails.
    }
}

} // namespace wf
