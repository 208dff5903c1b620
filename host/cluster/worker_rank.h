// worker_rank.h — a rank other than 0. It loads the scene and readies its
// devices as rank 0 does, tells rank 0 it is ready (or why it is not), then
// serves each of its devices' units in a thread of its own until rank 0 ends
// the work. It writes no file and prints nothing: rank 0 does both.
#pragma once

#include "session/render_options.h"

namespace wf {

// Returns the rank's exit status: 0, or 128 + the signal that stopped it. A
// failed set-up is reported to rank 0, which names it; the rank then returns 0
// and leaves the exit status to rank 0.
int serve_units(const RenderOptions& options);

} // namespace wf
