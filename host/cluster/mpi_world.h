// mpi_world.h — this process as one rank of several that `mpirun` started:
// MPI's lifetime, and the ranks' roles. Rank 0 renders like a single process
// and hands units of work to the devices of every other rank
// (rank_zero.h); the others serve units until told to end (worker_rank.h).
#pragma once

#include <string>

namespace wf {

class MpiWorld {
public:
    // MPI_Init_thread with MPI_THREAD_MULTIPLE, which rank 0's worker threads
    // need (each talks to one remote device); errors come back as codes.
    MpiWorld(int* argc, char*** argv);
    ~MpiWorld();
    MpiWorld(const MpiWorld&) = delete;
    MpiWorld& operator=(const MpiWorld&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }

private:
    int rank_ = 0, size_ = 1;
};

// Throws std::runtime_error naming `what` and MPI's message unless `code` is MPI_SUCCESS.
void check_mpi(int code, const std::string& what);

} // namespace wf
