// mpi_world.cpp — MPI_Init_thread and MPI_Finalize, and MPI's errors as exceptions.
#include "cluster/mpi_world.h"

#include <stdexcept>

#include <mpi.h>

namespace wf {

MpiWorld::MpiWorld(int* argc, char*** argv) {
    int provided = 0;
    check_mpi(MPI_Init_thread(argc, argv, MPI_THREAD_MULTIPLE, &provided), "MPI_Init_thread");
    if (provided < MPI_THREAD_MULTIPLE) {
        MPI_Finalize();
        throw std::runtime_error("this MPI library offers no MPI_THREAD_MULTIPLE, which rank 0's threads need");
    }
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiWorld::~MpiWorld() { MPI_Finalize(); }

void check_mpi(int code, const std::string& what) {
    if (code == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw std::runtime_error(what + " failed: " + std::string(text, static_cast<size_t>(length)));
}

} // namespace wf
