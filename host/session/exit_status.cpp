// exit_status.cpp — an OpenCL failure names the call and its code.
#include "session/exit_status.h"

#include <iostream>

#include <CL/opencl.hpp>

#include "base/errors.h"

namespace wf {

Failure describe_exception() {
    try {
        throw;
    } catch (const InputError& e) {
        return {2, e.what()};
    } catch (const DeviceError& e) {
        return {1, e.what()};
    } catch (const cl::Error& e) {
        return {1, std::string("OpenCL call ") + e.what() + " failed with code " + std::to_string(e.err())};
    } catch (const std::exception& e) {
        return {1, e.what()};
    } catch (...) {
        return {1, "an unknown failure"};
    }
}

int report_exception() {
    const Failure failure = describe_exception();
    std::cerr << "error: " << failure.message << "\n";
    return failure.exit_code;
}

} // namespace wf
