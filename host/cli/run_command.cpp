// run_command.cpp — a render under mpirun goes to the ranks (host/cluster/),
// any other to run_render(); --quiet leaves the errors alone, which reach
// stderr as exceptions.
#include "cli/run_command.h"

#include <csignal>
#include <iostream>

#include "base/errors.h"
#include "cli/cli.h"
#include "cluster/cluster_render.h"
#include "device/opencl_device.h"
#include "session/exit_status.h"
#include "session/kernel_cache.h"
#include "session/run_render.h"

namespace wf {
namespace {

std::string mib(size_t bytes) { return std::to_string((bytes + 1048575) / 1048576) + " MiB"; }

// `wavefront devices`: every OpenCL device with its index.
void print_devices(std::ostream& out) {
    for (const DeviceInfo& d : list_devices())
        out << "[" << d.index << "] " << d.name << "\n    type " << d.type << ", " << d.compute_units
            << " compute units, " << mib(d.global_memory) << " global memory (" << mib(d.max_allocation)
            << " per buffer)\n    platform " << d.platform << ", " << d.version << ", driver " << d.driver << "\n";
}

int run_command(const CommandLine& cl, VersionText version_text) {
    switch (cl.command) {
    case Command::Help:
        if (!cl.help.empty()) std::cout << cl.help << "\n";
        return 0;
    case Command::Version:
        std::cout << version_text();
        return 0;
    case Command::Devices:
        print_devices(std::cout);
        return 0;
    case Command::CacheWarm:
        warm_cache(cl.cache, std::cout);
        return 0;
    case Command::CacheClear:
        clear_cache(cl.cache, std::cout);
        return 0;
    case Command::Render: {
        std::ostream quiet(nullptr);
        std::ostream& out = cl.render.quiet ? quiet : std::cout;
        std::ostream& log = cl.render.quiet ? quiet : std::cerr;
        if (ranks_launched() > 1) {
#ifdef WF_HAVE_MPI
            return render_on_ranks(cl.render, out, log);
#else
            throw DeviceError("started by mpirun as " + std::to_string(ranks_launched()) +
                              " ranks, but built without MPI: install libopenmpi-dev "
                              "(scripts/setup.sh does) and build again");
#endif
        }
        const RenderSummary summary = run_render(cl.render, out, log);
        print_report(out, summary);
        return summary.interrupted_by ? 128 + summary.interrupted_by : 0; // as a shell reports a signal
    }
    }
    return 1;
}

} // namespace

int run_command_line(int argc, const char** argv, VersionText version_text) {
    // A reader that goes away (`| head -1`) must not cost the render: with
    // SIGPIPE ignored, a write to the closed pipe fails quietly and the streams
    // drop what follows, while the images are still written and the exit code
    // is the render's own.
    std::signal(SIGPIPE, SIG_IGN);
    try {
        return run_command(parse_command_line(argc, argv), version_text);
    } catch (...) {
        // Under mpirun every rank meets the same bad flag or file: rank 0 says so once.
        if (rank_launched() != 0) return describe_exception().exit_code;
        return report_exception();
    }
}

} // namespace wf
