// unit_worker.h — what takes units of work in a render shared by several
// devices (renderer.h): a device of this process (device_renderer.h), or one
// of another MPI rank (host/cluster/remote_device.h).
#pragma once

#include <cstdint>
#include <string>

#include "film/film.h"
#include "integrator/path_integrator.h"

namespace wf {

class UnitWorker {
public:
    virtual ~UnitWorker() = default;

    // Pixels [first, first + count) of `image` taken to `round_spp` samples
    // (count at most most_pixels()). Their sums are sent to the worker first
    // unless `held` (it has them already), and read back into `image` after.
    virtual void render_unit(uint32_t first, uint32_t count, uint32_t round_spp, FilmState& image, bool held) = 0;

    virtual std::string name() const = 0;     // for the report
    virtual uint32_t most_pixels() const = 0; // its pool: one slot a pixel
    // What it has traced so far, without the counter reads.
    virtual RenderStats counts() const = 0;
    // Spent moving units' sums between the host's image and the worker.
    virtual double transfer_seconds() const = 0;
};

} // namespace wf
