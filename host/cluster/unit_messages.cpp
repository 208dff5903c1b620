// unit_messages.cpp — a setup is lines of text; counts are a plain struct;
// messages are probed for their size before they are received.
#include "cluster/unit_messages.h"

#include <chrono>
#include <climits>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <mpi.h>

#include "cluster/mpi_world.h"

namespace wf {

UnitCounts to_wire(const RenderStats& c, double transfer_seconds, double unit_seconds) {
    UnitCounts w{};
    w.samples = c.samples;
    w.closest_rays = c.closest_rays;
    w.shadow_rays = c.shadow_rays;
    w.nonfinite_samples = c.nonfinite_samples;
    w.lane_paths = c.lane_paths;
    w.lane_slots = c.lane_slots;
    w.iterations = c.iterations;
    w.pool_bytes = c.pool_bytes;
    w.pool_size = c.pool_size;
    w.seconds = c.seconds;
    w.transfer_seconds = transfer_seconds;
    w.unit_seconds = unit_seconds;
    for (int s = 0; s < STAGE_COUNT; ++s) {
        w.stage_seconds[s] = c.stages[s].seconds;
        w.stage_launches[s] = c.stages[s].launches;
    }
    for (int b = 0; b < WF_PATH_LENGTH_BUCKETS; ++b) w.path_lengths[b] = c.path_lengths[b];
    return w;
}

RenderStats from_wire(const UnitCounts& w) {
    RenderStats c;
    c.samples = w.samples;
    c.closest_rays = w.closest_rays;
    c.shadow_rays = w.shadow_rays;
    c.nonfinite_samples = w.nonfinite_samples;
    c.lane_paths = w.lane_paths;
    c.lane_slots = w.lane_slots;
    c.iterations = w.iterations;
    c.pool_bytes = w.pool_bytes;
    c.pool_size = w.pool_size;
    c.seconds = w.seconds;
    for (int s = 0; s < STAGE_COUNT; ++s) {
        c.stages[s].seconds = w.stage_seconds[s];
        c.stages[s].launches = w.stage_launches[s];
    }
    for (int b = 0; b < WF_PATH_LENGTH_BUCKETS; ++b) c.path_lengths[b] = w.path_lengths[b];
    return c;
}

std::string encode_setup(const RankSetup& s) {
    std::ostringstream out;
    if (!s.error.empty()) {
        out << "error\n" << s.error;
        return out.str();
    }
    out << "ready\n" << s.scene_contents << "\n" << s.width << " " << s.height << "\n";
    for (const auto& [name, pool] : s.devices) out << pool << " " << name << "\n";
    return out.str();
}

RankSetup decode_setup(const std::string& text) {
    std::istringstream in(text);
    std::string kind;
    std::getline(in, kind);
    RankSetup s;
    if (kind == "error") {
        s.error = text.substr(kind.size() + 1);
        return s;
    }
    std::getline(in, s.scene_contents);
    in >> s.width >> s.height;
    uint32_t pool = 0;
    std::string name;
    while (in >> pool && std::getline(in >> std::ws, name)) s.devices.emplace_back(name, pool);
    return s;
}

void send_bytes(const void* data, size_t size, int rank, int tag, const std::string& what) {
    if (size > size_t{INT_MAX}) throw std::runtime_error(what + ": a message of " + std::to_string(size) + " bytes");
    check_mpi(MPI_Send(data, static_cast<int>(size), MPI_BYTE, rank, tag, MPI_COMM_WORLD), what);
}

namespace {

std::vector<unsigned char> receive_probed(int rank, int tag, const MPI_Status& status, const std::string& what) {
    int size = 0;
    MPI_Get_count(&status, MPI_BYTE, &size);
    std::vector<unsigned char> bytes(static_cast<size_t>(size));
    check_mpi(MPI_Recv(bytes.data(), size, MPI_BYTE, rank, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), what);
    return bytes;
}

} // namespace

std::vector<unsigned char> receive_bytes(int rank, int tag, const std::string& what) {
    MPI_Status status;
    check_mpi(MPI_Probe(rank, tag, MPI_COMM_WORLD, &status), what);
    return receive_probed(rank, tag, status, what);
}

std::optional<std::vector<unsigned char>> receive_bytes_unless(int rank, int tag, const std::string& what,
                                                               const std::function<bool()>& give_up) {
    MPI_Status status;
    for (int arrived = 0;;) {
        check_mpi(MPI_Iprobe(rank, tag, MPI_COMM_WORLD, &arrived, &status), what);
        if (arrived) return receive_probed(rank, tag, status, what);
        if (give_up()) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

} // namespace wf
