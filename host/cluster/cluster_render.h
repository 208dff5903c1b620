// cluster_render.h — `mpirun -np N wavefront render ...`: the render shared by
// every rank's devices. Rank 0 loads, renders with its own devices and those
// of the other ranks, and writes every file; the others serve units
// (worker_rank.h). Built only with MPI (WF_HAVE_MPI); ranks_launched() is
// always there, so that a build without MPI can refuse to run as N copies.
#pragma once

#include <cstdlib>
#include <iosfwd>

#include "session/render_options.h"

namespace wf {

// How many ranks mpirun started, and which this process is, from the
// environment it gives each (Open MPI's mpirun; MPICH's and Slurm's);
// 1 and 0 when it did not start this process.
inline int ranks_launched() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* v = std::getenv(name); v && std::atoi(v) > 1) return std::atoi(v);
    return 1;
}
inline int rank_launched() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK"})
        if (const char* v = std::getenv(name)) return std::atoi(v);
    return 0;
}

// The render on every rank; rank 0 prints the report on `out`. Returns the
// exit status: 0, or 128 + the signal that stopped the render. Throws as
// run_render() does.
int render_on_ranks(const RenderOptions& options, std::ostream& out, std::ostream& log);

} // namespace wf
