#include "mpi/mpi_communicator.hpp"

#include <numeric>
#include <stdexcept>
#include <string>

namespace sbpack {

void checkMpi(int status, const char* what) {
    if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

MpiSession::MpiSession(int& argc, char**& argv) {
    int provided = 0;
    checkMpi(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
}

MpiSession::~MpiSession() {
    MPI_Finalize();
}

MpiCommunicator::MpiCommunicator(MPI_Comm comm) : comm_(comm) {
    checkMpi(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
    checkMpi(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
    grids_ = makeMpiGrids(*this);
}

MpiCommunicator::~MpiCommunicator() = default;

std::vector<std::string> MpiCommunicator::allGather(const std::string& bytes) const {
    if (bytes.size() > static_cast<std::size_t>(INT32_MAX))
        throw std::runtime_error("MPI: a rank's records exceed 2 GB");
    const int mine = static_cast<int>(bytes.size());
    std::vector<int> counts(size_), offsets(size_, 0);
    checkMpi(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_), "MPI_Allgather");
    std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
    std::string all(static_cast<std::size_t>(offsets.back()) + counts.back(), '\0');
    checkMpi(MPI_Allgatherv(bytes.data(), mine, MPI_CHAR, all.data(), counts.data(), offsets.data(),
                            MPI_CHAR, comm_),
             "MPI_Allgatherv");
    std::vector<std::string> parts;
    for (int r = 0; r < size_; ++r)
        parts.push_back(all.substr(offsets[r], counts[r]));
    return parts;
}

void MpiCommunicator::sum(std::span<double> values) const {
    checkMpi(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE,
                           MPI_SUM, comm_),
             "MPI_Allreduce");
}

void MpiCommunicator::sum(std::span<std::int64_t> values) const {
    checkMpi(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()),
                           MPI_INT64_T, MPI_SUM, comm_),
             "MPI_Allreduce");
}

void MpiCommunicator::max(std::span<double> values) const {
    checkMpi(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE,
                           MPI_MAX, comm_),
             "MPI_Allreduce");
}

} // namespace sbpack
