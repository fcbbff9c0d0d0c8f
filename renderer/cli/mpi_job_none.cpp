// MpiJob in a build without MPI (CMake did not find it): --mpi is an error that says how to get it.
#include "cli/mpi_job.h"

#include <cstdlib>

namespace wavelit::cli {

util::Result<std::unique_ptr<MpiJob>> MpiJob::start() {
    return util::makeError(util::ErrorKind::Unsupported, "",
                           "--mpi: this wavelit-cli was built without MPI (install an MPI such as "
                           "Debian's libopenmpi-dev and rebuild; docs/farm.md)");
}

MpiJob::~MpiJob() = default;

util::Result<std::vector<double>> MpiJob::sumToRoot(const std::vector<double>& values) {
    return values; // one rank: its own sums
}

void MpiJob::abort(int code) {
    std::exit(code);
}

} // namespace wavelit::cli
