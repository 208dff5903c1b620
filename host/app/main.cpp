// main.cpp — `wavefront`: the command dispatch and the exit-code policy.
//   0 success · 1 the machine failed (no OpenCL device, a kernel that will not
//   build) · 2 the input is at fault (a scene, a flag, an output path) ·
//   128 + signal: a render stopped by Ctrl-C or SIGTERM, its image written.
// Every failure is one line on stderr that names the thing at fault.
#include <csignal>
#include <iostream>

#include "base/errors.h"
#include "cli/cli.h"
#include "cluster/cluster_render.h"
#include "cli/exit_status.h"
#include "cli/render_command.h"
#include "cli/version_text.h"

int main(int argc, const char** argv) {
    // A reader that goes away (`| head -1`) must not cost the render: with
    // SIGPIPE ignored, a write to the closed pipe fails quietly and the streams
    // drop what follows, while the images are still written and the exit code
    // is the render's own.
    std::signal(SIGPIPE, SIG_IGN);
    try {
        const wf::CommandLine cl = wf::parse_command_line(argc, argv);
        switch (cl.command) {
        case wf::Command::Help:
            if (!cl.help.empty()) std::cout << cl.help << "\n";
            return 0;
        case wf::Command::Version:
            std::cout << wf::version_text();
            return 0;
        case wf::Command::Devices:
            wf::print_devices(std::cout);
            return 0;
        case wf::Command::CacheWarm:
            wf::warm_cache(cl.cache, std::cout);
            return 0;
        case wf::Command::CacheClear:
            wf::clear_cache(cl.cache, std::cout);
            return 0;
        case wf::Command::Render: {
            // --quiet: errors only, which reach stderr as exceptions, below.
            std::ostream quiet(nullptr);
            std::ostream& out = cl.render.quiet ? quiet : std::cout;
            std::ostream& log = cl.render.quiet ? quiet : std::cerr;
            if (wf::ranks_launched() > 1) {
#ifdef WF_HAVE_MPI
                return wf::render_on_ranks(cl.render, out, log);
#else
                throw wf::DeviceError("started by mpirun as " + std::to_string(wf::ranks_launched()) +
                                      " ranks, but built without MPI: install libopenmpi-dev "
                                      "(scripts/setup.sh does) and build again");
#endif
            }
            const wf::RenderSummary summary = wf::run_render(cl.render, out, log);
            wf::print_report(out, summary);
            return summary.interrupted_by ? 128 + summary.interrupted_by : 0; // as a shell reports a signal
        }
        }
    } catch (...) {
        // Under mpirun every rank meets the same bad flag or file: rank 0 says so once.
        if (wf::rank_launched() != 0) return wf::describe_exception().exit_code;
        return wf::report_exception();
    }
    return 1;
}
