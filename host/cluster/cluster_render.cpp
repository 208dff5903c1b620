// cluster_render.cpp — rank 0's render is run_render()'s, with the other
// ranks' devices added as workers; they are told the work is over before MPI
// ends, whether the render succeeded or not.
#include "cluster/cluster_render.h"

#include <iostream>

#include "base/file_fingerprint.h"
#include "cluster/mpi_world.h"
#include "cluster/rank_zero.h"
#include "cluster/worker_rank.h"
#include "session/exit_status.h"
#include "session/interrupt.h"
#include "session/run_render.h"

namespace wf {

int render_on_ranks(const RenderOptions& options, std::ostream& out, std::ostream& log) {
    MpiWorld world(nullptr, nullptr);
    if (world.rank() != 0) {
        try {
            return serve_units(options);
        } catch (...) { // its set-up's failures went to rank 0; this is MPI's or a device's
            const Failure failure = describe_exception();
            std::cerr << "error: rank " << world.rank() << ": " << failure.message << "\n";
            return failure.exit_code;
        }
    }
    RenderOptions on_ranks = options;
    on_ranks.ranks = world.size();
    RenderSummary summary;
    {
        OtherRanks others(world.size());
        RenderHooks hooks;
        hooks.add_workers = [&](Renderer& renderer, ImageSize size) {
            renderer.add_workers(others.join(file_fingerprint(options.scene), size, &install_interrupt_handlers()));
        };
        summary = run_render(on_ranks, out, log, hooks);
    } // every device of the other ranks is told the work is over
    print_report(out, summary);
    return summary.interrupted_by ? 128 + summary.interrupted_by : 0;
}

} // namespace wf
