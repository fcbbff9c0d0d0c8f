// The `wavelit-cli wavelet product|sample` contract (architecture.md §6), run as a user would: small EXR
// files written with scene::writeExr into a temporary folder, the CLI started through
// WAVELIT_CLI_PATH, results checked against pixel-domain brute force and chi-square.
#include "scene/image_io.h"
#include "util/chi_square.h"
#include "util/rng.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace wavelit {
namespace {

namespace fs = std::filesystem;

// EXR stores float: each product texel is rounded once on input (per factor) and once on output,
// plus double arithmetic in between: a few 2^-24 relative.
constexpr double kFloatProductTolerance = 8.0 * 0x1p-24;
// CSV pdfs are printed with 9 significant digits, and the sampler's float tables are accurate to
// ~1e-6 relative at these levels (hierarchical_sampler_test).
constexpr double kCsvPdfTolerance = 1e-5;
constexpr double kChiSquareAlpha = 0.01;

struct CliRun {
    int exitCode = -1;
    std::string err;
};

class WaveletCli : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("wavelit_wavelet_cli_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string path(const std::string& name) const { return (m_dir / name).string(); }

    std::string write(const std::string& name, const util::ImageRGB& image) {
        const std::string p = path(name);
        EXPECT_TRUE(scene::writeExr(p, image).ok()) << p;
        return p;
    }

    CliRun run(const std::string& args) {
        const std::string errFile = path("stderr.txt");
        const std::string cmd = std::string("'") + WAVELIT_CLI_PATH + "' wavelet " + args +
                                " >/dev/null 2>'" + errFile + "'";
        const int status = std::system(cmd.c_str());
        CliRun r;
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        std::ifstream in(errFile);
        std::stringstream ss;
        ss << in.rdbuf();
        r.err = ss.str();
        return r;
    }

    fs::path m_dir;
};

util::ImageRGB randomImage(int w, int h, uint64_t seed, float lo = 0.1f, float hi = 2.0f) {
    util::Pcg32 rng(seed);
    util::ImageRGB img(w, h);
    for (auto& p : img.pixels)
        p = glm::vec3(lo + (hi - lo) * rng.nextFloat(), lo + (hi - lo) * rng.nextFloat(),
                      lo + (hi - lo) * rng.nextFloat());
    return img;
}

TEST_F(WaveletCli, ProductMatchesThePixelProductBothMethods) {
    const util::ImageRGB a = randomImage(16, 16, 1), b = randomImage(16, 16, 2),
                         c = randomImage(16, 16, 3);
    const std::string pa = write("a.exr", a), pb = write("b.exr", b), pc = write("c.exr", c);
    for (const char* method : {"dense", "sparse"}) {
        const std::string out = path(std::string("out_") + method + ".exr");
        CliRun r = run("product '" + pa + "' '" + pb + "' '" + pc + "' -o '" + out + "' --method " +
                       method);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        auto loaded = scene::loadImage(out);
        ASSERT_TRUE(loaded.ok());
        ASSERT_EQ(loaded->image.width, 16);
        for (size_t i = 0; i < a.pixels.size(); ++i)
            for (int ch = 0; ch < 3; ++ch) {
                const double expected = double(a.pixels[i][ch]) * b.pixels[i][ch] * c.pixels[i][ch];
                EXPECT_NEAR(loaded->image.pixels[i][ch], expected,
                            kFloatProductTolerance * expected)
                    << method;
            }
    }
    // A truncated product runs and reports its choice; --keep as a percentage too.
    EXPECT_EQ(
        run("product '" + pa + "' '" + pb + "' -o '" + path("k.exr") + "' --keep 10").exitCode, 0);
    EXPECT_EQ(
        run("product '" + pa + "' '" + pb + "' -o '" + path("k.exr") + "' --keep 5%").exitCode, 0);
}

TEST_F(WaveletCli, SampleWritesUvPdfFollowingTheLuminanceProduct) {
    const int side = 32;
    util::ImageRGB sky = randomImage(side, side, 4, 0.2f, 1.0f);
    sky.at(20, 5) = glm::vec3(500.0f, 400.0f, 300.0f); // a sun
    util::ImageRGB lobe(side, side);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const float d2 = float((x - 18) * (x - 18) + (y - 8) * (y - 8));
            lobe.at(x, y) = glm::vec3(std::exp(-d2 / 30.0f));
        }
    const std::string pa = write("sky.exr", sky), pb = write("lobe.exr", lobe), csv = path("s.csv");
    const int count = 100000;
    CliRun r = run("sample '" + pa + "' '" + pb + "' --count " + std::to_string(count) +
                   " --seed 7 -o '" + csv + "'");
    ASSERT_EQ(r.exitCode, 0) << r.err;

    // Expected: luminance of the per-channel product, normalised (unit-square density).
    std::vector<double> lum(size_t(side) * side);
    double total = 0.0;
    for (size_t i = 0; i < lum.size(); ++i) {
        const glm::dvec3 p = glm::dvec3(sky.pixels[i]) * glm::dvec3(lobe.pixels[i]);
        lum[i] = 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
        total += lum[i];
    }
    std::ifstream in(csv);
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line, "u,v,pdf");
    std::vector<double> observed(lum.size(), 0.0), expected(lum.size());
    int rows = 0;
    double worstPdf = 0.0;
    while (std::getline(in, line)) {
        double u, v, pdf;
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf", &u, &v, &pdf), 3) << line;
        ASSERT_TRUE(u >= 0 && u < 1 && v >= 0 && v < 1);
        const size_t texel = size_t(int(v * side)) * side + size_t(int(u * side));
        observed[texel] += 1;
        const double density = lum[texel] / total * side * side;
        worstPdf = std::max(worstPdf, std::abs(pdf - density) / density);
        ++rows;
    }
    EXPECT_EQ(rows, count);
    EXPECT_LT(worstPdf, kCsvPdfTolerance);
    for (size_t i = 0; i < lum.size(); ++i)
        expected[i] = lum[i] / total * count;
    EXPECT_GT(util::chiSquareTest(observed, expected).pValue, kChiSquareAlpha);
}

TEST_F(WaveletCli, BadInputIsExitOneNamingTheFile) {
    const std::string good = write("good.exr", randomImage(16, 16, 5));
    auto expectBad = [&](const std::string& args, const std::string& file,
                         const std::string& words) {
        CliRun r = run(args);
        EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    };
    const std::string wide = write("wide.exr", randomImage(32, 16, 6));
    expectBad("product '" + good + "' '" + wide + "' -o '" + path("o.exr") + "'", "wide.exr",
              "not square");
    const std::string npot = write("npot.exr", randomImage(24, 24, 7));
    expectBad("sample '" + npot + "' --count 10 -o '" + path("o.csv") + "'", "npot.exr",
              "power of two");
    util::ImageRGB nanImage = randomImage(16, 16, 8);
    nanImage.at(3, 4).g = std::nanf("");
    const std::string nan = write("nan.exr", nanImage);
    expectBad("product '" + good + "' '" + nan + "' -o '" + path("o.exr") + "'", "nan.exr",
              "texel"); // the loader reports "non-finite texel value at (3, 4)"
    const std::string smaller = write("small.exr", randomImage(8, 8, 9));
    expectBad("product '" + good + "' '" + smaller + "' -o '" + path("o.exr") + "'", "small.exr",
              "does not match");
    expectBad("product '" + good + "' '" + path("missing.exr") + "' -o '" + path("o.exr") + "'",
              "missing.exr", "");

    // All-zero product: the factors' supports do not overlap.
    util::ImageRGB left(16, 16), right(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 8; ++x)
            left.at(x, y) = glm::vec3(1.0f), right.at(x + 8, y) = glm::vec3(1.0f);
    const std::string pl = write("left.exr", left), pr = write("right.exr", right);
    expectBad("sample '" + pl + "' '" + pr + "' --count 10 -o '" + path("o.csv") + "'", "left.exr",
              "all-zero");
}

TEST_F(WaveletCli, BadUsageIsExitTwo) {
    const std::string a = write("a.exr", randomImage(8, 8, 10));
    for (const std::string& args : {std::string(""), std::string("transform '") + a + "'",
                                    "product '" + a + "' '" + a + "' -o x.exr --bogus 1",
                                    "product '" + a + "' '" + a + "'", // no -o
                                    "product '" + a + "' -o x.exr",    // one image
                                    "product '" + a + "' '" + a + "' -o x.exr --method fast",
                                    "product '" + a + "' '" + a + "' -o x.exr --keep lots",
                                    "sample '" + a + "' -o x.csv", // no --count
                                    "sample '" + a + "' --count 0 -o x.csv",
                                    "sample '" + a + "' --count 10 --seed -3 -o x.csv"}) {
        EXPECT_EQ(run(args).exitCode, 2) << args;
    }
}

} // namespace
} // namespace wavelit
