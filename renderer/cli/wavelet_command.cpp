// wavelit-cli wavelet product|sample (architecture.md §6): the wavelet core on square image files.
//
//   wavelet product A.exr B.exr [C.exr ...] -o OUT.exr [--keep K] [--method dense|sparse]
//   wavelet sample A.exr [B.exr ...] --count N [--seed S] [--keep K] -o SAMPLES.csv
//
// Images are functions on the unit square (column x -> u = (x + 0.5) / W at texel centres, row 0
// the file's first, top row -> v). Each RGB channel is a factor of its own: channel c of the
// product is the product of channel c of every input. --keep K keeps the K largest Haar
// coefficients of every factor and channel (K may also be "P%" of the coefficients); without it the
// product is exact. sample draws from the luminance of the product (clamped to 0, normalised) and
// writes u,v,pdf with pdf in the unit-square measure. Exit codes: 0 ok, 1 bad input, 2 bad usage.
#include "cli/args.h"
#include "cli/commands.h"
#include "scene/image_io.h"
#include "util/rng.h"
#include "wavelet/hierarchical_sampler.h"
#include "wavelet/image_grid.h"
#include "wavelet/product.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wavelit::cli {
namespace {

using util::ErrorKind;
using util::makeError;
namespace wv = wavelet;

struct Factors {
    int level = 0;
    // channels[c][k]: channel c of input k.
    std::array<std::vector<wv::SparseHaar>, 3> channels;
    double worstRelativeL2 = 0.0; // truncation error left, worst over inputs and channels
    size_t keptPerFactor = 0;
};

// "--keep 1000" or "--keep 5%"; nullopt keeps everything.
util::Result<std::optional<double>> parseKeep(const Args& args) {
    auto text = args.value("--keep");
    if (!text)
        return std::optional<double>();
    std::string t = *text;
    const bool percent = !t.empty() && t.back() == '%';
    if (percent)
        t.pop_back();
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size() || !(v > 0.0) || (percent && v > 100.0) ||
        (!percent && v != double(size_t(v))))
        return makeError(ErrorKind::Usage, "",
                         "--keep must be a positive count or a percentage, got " + *text);
    return std::optional<double>(percent ? -v / 100.0 : v); // negative marks a fraction
}

// The positional images as factors, truncated per --keep.
util::Result<Factors> loadFactors(const Args& args) {
    auto keepFlag = parseKeep(args);
    if (!keepFlag)
        return keepFlag.error();
    const std::optional<double> keep = *keepFlag;
    const std::vector<std::string>& paths = args.positional();
    Factors out;
    int width = -1;
    std::string first;
    for (const std::string& path : paths) {
        scene::ImageLoadOptions options;
        options.sanitize = false; // NaN/Inf texels are an error naming the texel, not a silent 0
        auto loaded = scene::loadImage(path, options);
        if (!loaded)
            return loaded.error();
        const util::ImageRGB& img = loaded->image;
        for (int c = 0; c < 3; ++c) {
            auto grid = wv::channelGrid(img, c, path); // square, power of two, finite
            if (!grid)
                return grid.error();
            if (width < 0) {
                width = img.width;
                first = path;
                out.level = grid->level;
            } else if (img.width != width) {
                return makeError(ErrorKind::Invalid, path,
                                 std::to_string(img.width) + "x" + std::to_string(img.height) +
                                     " does not match " + first + " (" + std::to_string(width) +
                                     "x" + std::to_string(width) + ")");
            }
            const wv::HaarImage haar = wv::forwardHaar(*grid);
            if (!keep) {
                out.channels[size_t(c)].push_back(wv::sparsify(haar));
                out.keptPerFactor = haar.coeffs.size();
                continue;
            }
            const size_t k =
                *keep < 0.0 ? size_t(-*keep * double(haar.coeffs.size()) + 0.5) : size_t(*keep);
            wv::Truncation t = wv::truncate(haar, std::max<size_t>(1, k));
            out.worstRelativeL2 = std::max(out.worstRelativeL2, t.relativeL2);
            out.keptPerFactor = std::min(haar.coeffs.size(), std::max<size_t>(1, k));
            out.channels[size_t(c)].push_back(std::move(t.coefficients));
        }
    }
    return out;
}

util::Status writeCsv(const std::string& path, const wv::HierarchicalSampler& sampler,
                      long long count, uint64_t seed) {
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
    if (!file)
        return makeError(ErrorKind::Io, path, "cannot open for writing");
    util::Pcg32 rng(seed);
    std::fputs("u,v,pdf\n", file.get());
    for (long long i = 0; i < count; ++i) {
        const double u1 = rng.nextDouble(), u2 = rng.nextDouble();
        const wv::SquareSample s = sampler.sample({u1, u2});
        std::fprintf(file.get(), "%.9g,%.9g,%.9g\n", s.point.x, s.point.y, s.pdf);
    }
    if (std::fflush(file.get()) != 0 || std::ferror(file.get()))
        return makeError(ErrorKind::Io, path, "write failed");
    return util::okStatus();
}

int runProduct(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, {"-o", "--keep", "--method"});
    if (!args)
        return reportError(args.error());
    const auto& inputs = args->positional();
    if (inputs.size() < 2)
        return reportError(
            makeError(ErrorKind::Usage, "", "wavelet product needs at least two images"));
    auto out = args->value("-o");
    if (!out)
        return reportError(makeError(ErrorKind::Usage, "", "wavelet product needs -o OUT.exr"));
    auto method = args->value("--method");
    if (method && *method != "dense" && *method != "sparse")
        return reportError(
            makeError(ErrorKind::Usage, "", "--method must be dense or sparse, got " + *method));
    auto factors = loadFactors(*args);
    if (!factors)
        return reportError(factors.error());

    // Without --method the choice follows the library's crossover density
    // (wavelet::kSparseCrossoverDensity, docs/wavelet-benchmarks.md); the green channel decides
    // for all three so the report names one path.
    const auto green = wv::factorPointers(factors->channels[1]);
    const bool sparse =
        method ? *method == "sparse" : wv::meanDensity(green) < wv::kSparseCrossoverDensity;
    const int side = 1 << factors->level;
    util::ImageRGB image(side, side);
    for (int c = 0; c < 3; ++c) {
        const auto list = wv::factorPointers(factors->channels[size_t(c)]);
        const wv::SquareGrid grid =
            wv::product(list, sparse ? wv::ProductMethod::Sparse : wv::ProductMethod::Dense)
                .toGrid();
        for (size_t i = 0; i < grid.values.size(); ++i)
            image.pixels[i][c] = float(grid.values[i]);
    }
    if (auto written = scene::writeExr(*out, image); !written)
        return reportError(written.error());
    std::printf(
        "wavelet product: %zu factors, %dx%d, %s path, %zu coefficients kept per factor and channel"
        " (worst relative L2 truncation error %.3g)\n",
        inputs.size(), side, side, sparse ? "sparse" : "dense", factors->keptPerFactor,
        factors->worstRelativeL2);
    return 0;
}

int runSample(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, {"-o", "--count", "--seed", "--keep"});
    if (!args)
        return reportError(args.error());
    const auto& inputs = args->positional();
    if (inputs.empty())
        return reportError(
            makeError(ErrorKind::Usage, "", "wavelet sample needs at least one image"));
    auto out = args->value("-o");
    if (!out)
        return reportError(makeError(ErrorKind::Usage, "", "wavelet sample needs -o SAMPLES.csv"));
    if (!args->has("--count"))
        return reportError(makeError(ErrorKind::Usage, "", "wavelet sample needs --count N"));
    auto count = args->intValue("--count", 0, 1, 100000000);
    if (!count)
        return reportError(count.error());
    auto seed = args->uint64Value("--seed", 0);
    if (!seed)
        return reportError(seed.error());
    auto factors = loadFactors(*args);
    if (!factors)
        return reportError(factors.error());

    // Luminance of the RGB product (architecture.md §6), then its full pyramid for sampling.
    constexpr double kLuminance[3] = {0.2126, 0.7152, 0.0722};
    wv::SquareGrid luminance(factors->level);
    for (int c = 0; c < 3; ++c) {
        const auto list = wv::factorPointers(factors->channels[size_t(c)]);
        const wv::SquareGrid grid = wv::product(list).toGrid();
        for (size_t i = 0; i < grid.values.size(); ++i)
            luminance.values[i] += kLuminance[c] * grid.values[i];
    }
    auto sampler = wv::HierarchicalSampler::build(wv::ScalingTree::fromGrid(luminance));
    if (!sampler) {
        std::string names;
        for (const std::string& p : inputs)
            names += (names.empty() ? "" : " x ") + p;
        return reportError(makeError(ErrorKind::Invalid, names, sampler.error().reason));
    }
    if (auto written = writeCsv(*out, *sampler, *count, *seed); !written)
        return reportError(written.error());
    return 0;
}

} // namespace

int runWavelet(const std::vector<std::string>& args) {
    if (args.empty())
        return reportError(
            makeError(ErrorKind::Usage, "", "wavelet needs a subcommand: product or sample"));
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "product")
        return runProduct(rest);
    if (args[0] == "sample")
        return runSample(rest);
    return reportError(makeError(
        ErrorKind::Usage, "", "unknown wavelet subcommand '" + args[0] + "' (product or sample)"));
}

} // namespace wavelit::cli
