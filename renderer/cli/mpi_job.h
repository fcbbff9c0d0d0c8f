// One process of `mpirun -n N wavelit-cli render ... --mpi` (issue 17, docs/farm.md): MPI is the
// distributed engine, Wavelit only splits passes and sums. Built from mpi_job.cpp when CMake finds
// MPI, else from mpi_job_none.cpp, whose start() says the build has no MPI support.
#pragma once

#include "util/result.h"

#include <memory>
#include <vector>

namespace wavelit::cli {

class MpiJob {
public:
    // MPI_Init; an Unsupported error when this build has no MPI support.
    static util::Result<std::unique_ptr<MpiJob>> start();
    ~MpiJob(); // MPI_Finalize
    MpiJob(const MpiJob&) = delete;
    MpiJob& operator=(const MpiJob&) = delete;

    int rank() const { return m_rank; }
    int size() const { return m_size; }
    // Sums every rank's `values` (all of one length) element-wise into rank 0's; rank 0 gets the
    // sums, the other ranks an empty vector. Collective: every rank must call it.
    util::Result<std::vector<double>> sumToRoot(const std::vector<double>& values);
    // Ends every rank of the job with `code` (MPI_Abort): a rank that failed must not leave the
    // others waiting in sumToRoot.
    [[noreturn]] void abort(int code);

private:
    MpiJob(int rank, int size) : m_rank(rank), m_size(size) {}
    int m_rank = 0, m_size = 1;
};

} // namespace wavelit::cli
