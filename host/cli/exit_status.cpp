// exit_status.cpp — an OpenCL failure names the call and its code.
#include "cli/exit_status.h"

#include <iostream>

#include <CL/opencl.hpp>

#include "base/errors.h"

namespace wf {

int report_exception() {
    try {
        throw;
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    } catch (const DeviceError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    } catch (const cl::Error& e) {
        std::cerr << "error: OpenCL call " << e.what() << " failed with code " << e.err() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    } catch (...) {
        std::cerr << "error: an unknown failure\n";
        return 1;
    }
}

} // namespace wf
