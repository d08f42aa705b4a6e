#include "mpi/distributed_distance_transform.hpp"

#include "parallel/parallel.hpp"
#include "pores/distance_transform.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace sbpack {

namespace {

/// The passes along z (the first: 0 on solid, kNoSite on void) and y of an x-slab, in place.
void slabPasses(std::vector<std::uint32_t>& map, std::int64_t planes, int m,
                const Progress& progress) {
    const std::int64_t plane = std::int64_t{m} * m;
    parallelFor(0, planes, 1, [&](std::int64_t begin, std::int64_t end) {
        PeriodicLineTransform line(m);
        for (std::int64_t x = begin; x < end; ++x) {
            progress.checkInterrupt();
            std::uint32_t* p = map.data() + x * plane;
            for (int y = 0; y < m; ++y)
                line(p + std::int64_t{y} * m, 1);
            for (int z = 0; z < m; ++z)
                line(p + z, m);
        }
    });
}

/// Rows of M values: the unit of the transpose (counts stay far below 2^31).
class RowType {
  public:
    explicit RowType(int m) {
        checkMpi(MPI_Type_contiguous(m, MPI_UINT32_T, &type_), "MPI_Type_contiguous");
        checkMpi(MPI_Type_commit(&type_), "MPI_Type_commit");
    }
    RowType(const RowType&) = delete;
    RowType& operator=(const RowType&) = delete;
    ~RowType() { MPI_Type_free(&type_); }
    MPI_Datatype get() const { return type_; }

  private:
    MPI_Datatype type_{};
};

struct Layout {
    std::vector<int> counts, offsets; ///< in rows, per rank
};

Layout layout(std::vector<int> counts) {
    Layout l{std::move(counts), std::vector<int>(l.counts.size(), 0)};
    for (std::size_t r = 1; r < l.counts.size(); ++r)
        l.offsets[r] = l.offsets[r - 1] + l.counts[r - 1];
    return l;
}

/// x-slab ((x - x0) M + y) M + z  ->  y-slab ((y - y0) M + x) M + z, by one MPI_Alltoallv.
std::vector<std::uint32_t> transpose(const MpiCommunicator& comm, std::vector<std::uint32_t> map,
                                     int m, DistanceSlab& out) {
    const int ranks = comm.size(), rank = comm.rank();
    const Slab x = slabOf(m, ranks, rank);
    std::vector<int> sendRows(ranks), receiveRows(ranks);
    for (int s = 0; s < ranks; ++s) {
        sendRows[s] = x.size() * slabOf(m, ranks, s).size();
        receiveRows[s] = slabOf(m, ranks, s).size() * out.y.size();
    }
    const Layout send = layout(sendRows), receive = layout(receiveRows);
    const std::size_t row = static_cast<std::size_t>(m) * sizeof(std::uint32_t);
    std::vector<std::uint32_t> sendBuffer, received;
    // Allocations agreed on before the exchange: a rank out of memory stops all.
    collectively(comm, [&] {
        sendBuffer.resize(static_cast<std::size_t>(x.size()) * m * m);
        out.peakBytes = std::max(out.peakBytes, 2.0 * static_cast<double>(map.size()) * 4);
        for (int s = 0; s < ranks; ++s) { // to rank s: rows (x, y in s's y-slab), x-major
            const Slab ys = slabOf(m, ranks, s);
            for (int xl = 0; xl < x.size(); ++xl)
                std::memcpy(sendBuffer.data() + (static_cast<std::size_t>(send.offsets[s]) +
                                                 static_cast<std::size_t>(xl) * ys.size()) *
                                                    m,
                            map.data() + (static_cast<std::size_t>(xl) * m + ys.begin) * m,
                            row * ys.size());
            if (s != rank) out.sentBytes += static_cast<double>(sendRows[s]) * row;
        }
        map = {};
        received.resize(static_cast<std::size_t>(out.y.size()) * m * m);
        out.peakBytes =
            std::max(out.peakBytes, static_cast<double>(sendBuffer.size() + received.size()) * 4);
    });
    const RowType rowType(m);
    checkMpi(MPI_Alltoallv(sendBuffer.data(), send.counts.data(), send.offsets.data(),
                           rowType.get(), received.data(), receive.counts.data(),
                           receive.offsets.data(), rowType.get(), comm.comm()),
             "MPI_Alltoallv");
    sendBuffer = {};
    std::vector<std::uint32_t> slab;
    collectively(comm, [&] {
        slab.resize(received.size());
        out.peakBytes = std::max(out.peakBytes, 2.0 * static_cast<double>(received.size()) * 4);
        for (int s = 0; s < ranks; ++s) { // from rank s: rows (x in s's x-slab, y), x-major
            const Slab xs = slabOf(m, ranks, s);
            for (int xl = 0; xl < xs.size(); ++xl)
                for (int yl = 0; yl < out.y.size(); ++yl)
                    std::memcpy(
                        slab.data() + (static_cast<std::size_t>(yl) * m + xs.begin + xl) * m,
                        received.data() + (static_cast<std::size_t>(receive.offsets[s]) +
                                           static_cast<std::size_t>(xl) * out.y.size() + yl) *
                                              m,
                        row);
        }
    });
    return slab;
}

} // namespace

DistanceSlab distributedDistanceTransform(const MpiCommunicator& comm,
                                          std::span<const std::uint8_t> mask, int m,
                                          const Progress& progress) {
    const Slab x = slabOf(m, comm.size(), comm.rank());
    const std::size_t slabVoxels = static_cast<std::size_t>(x.size()) * m * m;
    if (mask.size() != slabVoxels)
        throw std::invalid_argument("distributed distance transform: the mask is not this rank's "
                                    "slab of " +
                                    std::to_string(x.size()) + " planes");
    DistanceSlab out;
    out.voxels = m;
    out.y = slabOf(m, comm.size(), comm.rank());
    std::vector<std::uint32_t> map;
    collectively(comm, [&] {
        map.resize(slabVoxels);
        std::transform(mask.begin(), mask.end(), map.begin(),
                       [](std::uint8_t v) { return v != 0 ? 0u : kNoSite; });
        out.peakBytes = static_cast<double>(slabVoxels) * (sizeof(std::uint8_t) + 4);
        slabPasses(map, x.size(), m, progress);
    });
    out.squared = transpose(comm, std::move(map), m, out);
    collectively(comm, [&] {
        const std::int64_t plane = std::int64_t{m} * m;
        std::vector<std::uint32_t> largest(static_cast<std::size_t>(out.y.size()), 0);
        parallelFor(0, out.y.size(), 1, [&](std::int64_t begin, std::int64_t end) {
            PeriodicLineTransform line(m);
            for (std::int64_t y = begin; y < end; ++y) {
                progress.checkInterrupt();
                for (int z = 0; z < m; ++z)
                    largest[y] = std::max(largest[y], line(out.squared.data() + y * plane + z, m));
            }
        });
        out.largest = largest.empty() ? 0 : *std::max_element(largest.begin(), largest.end());
    });
    double largest = out.largest;
    comm.max(std::span<double>(&largest, 1));
    out.largest = static_cast<std::uint32_t>(largest);
    return out;
}

} // namespace sbpack
