// interrupt.h — Ctrl-C (SIGINT) and SIGTERM during a render: the first asks
// the render to stop starting samples, finish the paths in flight and write
// what it has (run_render.cpp); a second ends the process at once.
#pragma once

#include <atomic>

namespace wf {

// Installs the handlers; the flag they set is the one returned. Safe to call more than once.
const std::atomic<int>& install_interrupt_handlers();

// The signal that asked the render to stop, or 0.
int interrupt_signal();

} // namespace wf
