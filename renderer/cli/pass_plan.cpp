#include "cli/pass_plan.h"

#include "util/path_util.h"

namespace wavelit::cli {

using util::ErrorKind;
using util::makeError;

util::Result<std::optional<PassRange>> fixedPasses(const Args& args, int spp, int maxSpp,
                                                   const std::string& output) {
    std::optional<PassRange> range;
    if (auto text = args.value("--passes")) {
        if (args.has("--spp") || args.has("--time"))
            return makeError(ErrorKind::Usage, "",
                             "--passes FIRST:COUNT sets the passes: leave out --spp and --time");
        auto parsed = parsePassRange("--passes", *text, maxSpp);
        if (!parsed) return parsed.error();
        range = *parsed;
    }
    if (args.has("--mpi")) {
        if (args.has("--time"))
            return makeError(ErrorKind::Usage, "",
                             "--mpi needs a pass count (--spp N or --passes FIRST:COUNT), not "
                             "--time");
        if (args.has("--trace-outliers") || args.has("--report"))
            return makeError(ErrorKind::Usage, "",
                             "--mpi does not take --trace-outliers or --report (they describe "
                             "one process)");
        if (!range) range = PassRange{0, spp};
    }
    if (range && util::lowerExtension(output) != ".exr")
        return makeError(ErrorKind::Usage, output,
                         "--passes and --mpi write a part for merge: -o must end in .exr");
    return range;
}

util::Result<util::ImageRGB> meanOverRanks(MpiJob& mpi, const util::ImageRGB& mean, int passes,
                                           int totalPasses) {
    std::vector<double> sum(mean.pixels.size() * 3);
    for (size_t i = 0; i < mean.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            sum[3 * i + size_t(c)] = double(mean.pixels[i][c]) * double(passes);
    auto total = mpi.sumToRoot(sum);
    if (!total) return total.error();
    if (mpi.rank() != 0) return util::ImageRGB{};
    util::ImageRGB out(mean.width, mean.height);
    for (size_t i = 0; i < out.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            out.pixels[i][c] = float((*total)[3 * i + size_t(c)] / double(totalPasses));
    return out;
}

} // namespace wavelit::cli
