#pragma once
// The processes of one sbanalyze run (docs/scale-out.md): one without MPI, the ranks of
// MPI_COMM_WORLD under mpirun (analysis/mpi/, built with SBPACK_WITH_MPI). The pipeline is the
// same code for one rank and many: it distributes the files (or the grids' slabs) over
// rank()/size(), agrees on errors before every collective that could block, and gathers the
// per-file records to rank 0, which runs the one ensemble reducer and writes the one results file.

#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

class DistributedGrids;

/// An error some rank met, known to every rank after agreeOnErrors: the message lists each
/// failing rank's error (rank 0 prints it; the others exit quietly with status 1).
class CollectiveError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class Communicator {
  public:
    virtual ~Communicator() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    /// Collective: every rank's `bytes`, in rank order, on every rank.
    virtual std::vector<std::string> allGather(const std::string& bytes) const = 0;
    /// Collective: element-wise sums over the ranks, in place on every rank.
    virtual void sum(std::span<double> values) const = 0;
    virtual void sum(std::span<std::int64_t> values) const = 0;
    /// Collective: element-wise maxima over the ranks, in place on every rank.
    virtual void max(std::span<double> values) const = 0;
    /// The distributed grid computations (--distribute grids); nullptr without MPI.
    virtual const DistributedGrids* grids() const { return nullptr; }
};

/// One process: rank 0 of 1; the collectives return their input.
class SerialCommunicator final : public Communicator {
  public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    std::vector<std::string> allGather(const std::string& bytes) const override { return {bytes}; }
    void sum(std::span<double>) const override {}
    void sum(std::span<std::int64_t>) const override {}
    void max(std::span<double>) const override {}
};

/// Collective: runs `work` on every rank. With one rank an exception passes unchanged; with
/// several every rank learns every rank's error (allGather) before any goes on, and all throw
/// CollectiveError naming each failing rank, so that none waits in a later collective.
void collectively(const Communicator& communicator, const std::function<void()>& work);

} // namespace sbpack
