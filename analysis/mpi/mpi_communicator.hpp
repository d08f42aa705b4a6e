#pragma once
// MPI_COMM_WORLD as the pipeline's Communicator (parallel/communicator.hpp; docs/scale-out.md),
// with the distributed grid computations of --distribute grids. Built with SBPACK_WITH_MPI only.

#include "parallel/communicator.hpp"
#include "pipeline/distributed_grids.hpp"

#include <mpi.h>

#include <memory>

namespace sbpack {

/// MPI_Init_thread (funneled: only the main thread calls MPI; TBB and OpenMP threads compute)
/// and MPI_Finalize.
class MpiSession {
  public:
    MpiSession(int& argc, char**& argv);
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    ~MpiSession();
};

class MpiCommunicator final : public Communicator {
  public:
    explicit MpiCommunicator(MPI_Comm comm = MPI_COMM_WORLD);
    ~MpiCommunicator() override;

    int rank() const override { return rank_; }
    int size() const override { return size_; }
    std::vector<std::string> allGather(const std::string& bytes) const override;
    void sum(std::span<double> values) const override;
    void sum(std::span<std::int64_t> values) const override;
    void max(std::span<double> values) const override;
    const DistributedGrids* grids() const override { return grids_.get(); }
    MPI_Comm comm() const { return comm_; }

  private:
    MPI_Comm comm_;
    int rank_ = 0, size_ = 1;
    std::unique_ptr<DistributedGrids> grids_;
};

/// The grid computations over the ranks of `comm` (mpi/mpi_grids.cpp).
std::unique_ptr<DistributedGrids> makeMpiGrids(const MpiCommunicator& comm);

/// Throws std::runtime_error naming `what` unless an MPI call returned MPI_SUCCESS.
void checkMpi(int status, const char* what);

} // namespace sbpack
