// interrupt.cpp — the handler only stores to a lock-free atomic, or calls
// _exit: both are async-signal-safe.
#include "session/interrupt.h"

#include <csignal>

#include <unistd.h>

namespace wf {
namespace {

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_interrupt(int sig) {
    int expected = 0;
    if (!g_signal.compare_exchange_strong(expected, sig)) _exit(128 + sig); // the second: at once
}

} // namespace

const std::atomic<int>& install_interrupt_handlers() {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    return g_signal;
}

int interrupt_signal() { return g_signal.load(); }

} // namespace wf
