// exit_status.h — the exit-code policy of every executable of the project, in
// one place: 2 when the input is at fault (InputError), 1 when the machine is
// (DeviceError, a failed OpenCL call, anything else), with one line on stderr.
// The Python module raises InputError or DeviceError by the same split.
#pragma once

#include <string>

namespace wf {

struct Failure {
    int exit_code = 1;
    std::string message; // one line, without "error: "
};

// Call from within a catch (...) block: the exception in flight as an exit
// code and a message.
Failure describe_exception();

// Call from within a catch (...) block: prints the exception in flight as
// "error: ..." and returns the exit code for it.
int report_exception();

} // namespace wf
