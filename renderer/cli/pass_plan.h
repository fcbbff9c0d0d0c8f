// Which passes `wavelit-cli render` runs when they are fixed (--passes FIRST:COUNT, --mpi), and
// the mean over the ranks of an MPI job (docs/farm.md).
#pragma once

#include "cli/args.h"
#include "cli/mpi_job.h"
#include "cli/partial_render.h"
#include "util/image.h"
#include "util/result.h"

#include <optional>
#include <string>

namespace wavelit::cli {

// The passes a render must run exactly (--passes FIRST:COUNT, or --mpi with --spp N: passes
// 0..N-1), or none when it runs from pass 0 until --spp or --time. Usage errors for flags that do
// not go with them (--spp/--time with --passes; --time, --trace-outliers, --report with --mpi)
// and for an `output` that is not an EXR (the pass count travels in its header).
util::Result<std::optional<PassRange>> fixedPasses(const Args& args, int spp, int maxSpp,
                                                   const std::string& output);

// The mean over every rank's passes, on rank 0 (an empty image on the others): a rank's sum is
// its mean times its pass count. Collective: every rank calls it.
util::Result<util::ImageRGB> meanOverRanks(MpiJob& mpi, const util::ImageRGB& mean, int passes,
                                           int totalPasses);

} // namespace wavelit::cli
