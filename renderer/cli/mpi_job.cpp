// MpiJob on MPI (Open MPI from Debian's libopenmpi-dev is what is tested; any MPI-3 works).
#include "cli/mpi_job.h"

#include <mpi.h>

#include <algorithm>
#include <cstdlib>

namespace wavelit::cli {

util::Result<std::unique_ptr<MpiJob>> MpiJob::start() {
    // Only the main thread calls MPI; the tracers' own threads never do.
    if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS)
        return util::makeError(util::ErrorKind::Device, "", "--mpi: MPI_Init failed");
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return std::unique_ptr<MpiJob>(new MpiJob(rank, size));
}

MpiJob::~MpiJob() {
    MPI_Finalize();
}

util::Result<std::vector<double>> MpiJob::sumToRoot(const std::vector<double>& values) {
    std::vector<double> sums(m_rank == 0 ? values.size() : 0);
    // MPI counts are int: a 16384^2 RGB image (805 M doubles) goes in chunks.
    constexpr size_t kChunk = size_t(1) << 26;
    for (size_t at = 0; at < values.size(); at += kChunk) {
        const int n = int(std::min(kChunk, values.size() - at));
        if (MPI_Reduce(values.data() + at, m_rank == 0 ? sums.data() + at : nullptr, n, MPI_DOUBLE,
                       MPI_SUM, 0, MPI_COMM_WORLD) != MPI_SUCCESS)
            return util::makeError(util::ErrorKind::Device, "", "--mpi: MPI_Reduce failed");
    }
    return sums;
}

void MpiJob::abort(int code) {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::exit(code); // MPI_Abort does not return; this keeps [[noreturn]] honest
}

} // namespace wavelit::cli
