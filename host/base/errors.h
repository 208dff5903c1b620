// errors.h — the two ways a run fails on purpose. Both carry a one-line message
// that names the thing at fault; main() prints it and exits with the code.
#pragma once

#include <stdexcept>
#include <string>

namespace wf {

// The user's input is wrong: a file, a flag, a scene the device cannot hold.
// Exit code 2.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The machine cannot do it: no OpenCL platform, a kernel that fails to build.
// Exit code 1.
struct DeviceError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace wf
