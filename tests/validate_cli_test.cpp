// `wavelit-cli validate` against the bad-input corpus (tests/data/bad/EXPECTED.md is the table of
// files, exit codes and message fragments) and the bundled resources (all must validate).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const fs::path kBad = fs::path(WAVELIT_TEST_DATA_DIR) / "bad";
const fs::path kResources = WAVELIT_RESOURCE_DIR;

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct CliRun {
    int exitCode = -1;
    std::string out, err;
};

CliRun validate(const std::vector<std::string>& args) {
    const fs::path tmp = fs::temp_directory_path() / ("wavelit_validate_" + std::to_string(::getpid()));
    std::string cmd = std::string("'") + WAVELIT_CLI_PATH + "' validate";
    for (const auto& a : args) cmd += " '" + a + "'";
    cmd += " >'" + tmp.string() + ".out' 2>'" + tmp.string() + ".err'";
    const int status = std::system(cmd.c_str());
    CliRun r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readText(tmp.string() + ".out");
    r.err = readText(tmp.string() + ".err");
    fs::remove(tmp.string() + ".out");
    fs::remove(tmp.string() + ".err");
    return r;
}

struct Expected {
    std::string file;
    int exitCode;
    std::string fragment;
};

std::vector<Expected> expectedRows() {
    std::vector<Expected> rows;
    std::istringstream lines(readText(kBad / "EXPECTED.md"));
    const std::regex row(R"(^\| `([^`]+)` \| ([01]) \| `(.+)` \|$)");
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_match(line, m, row)) rows.push_back({m[1], std::stoi(m[2]), m[3]});
    }
    return rows;
}

TEST(ValidateCli, EveryBadFileGivesItsDocumentedResult) {
    const auto rows = expectedRows();
    ASSERT_GE(rows.size(), 25u);
    std::set<std::string> listed;
    int errors = 0, warnings = 0;
    for (const auto& row : rows) {
        SCOPED_TRACE(row.file);
        listed.insert(row.file);
        ASSERT_TRUE(fs::exists(kBad / row.file));
        const CliRun r = validate({(kBad / row.file).string()});
        EXPECT_EQ(r.exitCode, row.exitCode) << r.err;
        EXPECT_NE(r.err.find(row.file), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(row.fragment), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
        // Sanitisable problems are reported as warnings, yet still fail validation.
        if (r.err.find("warning: ") != std::string::npos) {
            EXPECT_NE(r.err.find("that loading would repair"), std::string::npos) << r.err;
            ++warnings;
        } else {
            ++errors;
        }
    }
    // No file in the corpus without a row, so nothing goes untested.
    for (const auto& e : fs::directory_iterator(kBad))
        if (e.path().filename() != "EXPECTED.md") {
            EXPECT_TRUE(listed.count(e.path().filename().string())) << e.path();
        }
    EXPECT_GE(errors, 25);
    EXPECT_GE(warnings, 4);
}

// 10^6 identical vertices in 333,333 faces: generated here (~20 MB) rather than committed.
TEST(ValidateCli, MillionDuplicateVerticesAreAZeroAreaMesh) {
    const fs::path mesh = fs::temp_directory_path() / ("duplicate_vertices_1e6_" + std::to_string(::getpid()) + ".obj");
    {
        std::ofstream out(mesh);
        constexpr int kVertices = 1000000;
        for (int i = 0; i < kVertices; ++i) out << "v 0.5 0.25 -1\n";
        for (int i = 0; i + 3 <= kVertices; i += 3) out << "f " << i + 1 << ' ' << i + 2 << ' ' << i + 3 << '\n';
    }
    const CliRun r = validate({mesh.string()});
    fs::remove(mesh);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("duplicate_vertices_1e6_"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("all 333333 triangles have zero area"), std::string::npos) << r.err;
}

TEST(ValidateCli, EveryBundledResourceIsValid) {
    int files = 0;
    for (const char* folder : {"scenes", "lighting", "meshes", "envmaps"})
        for (const auto& e : fs::directory_iterator(kResources / folder)) {
            const CliRun r = validate({e.path().string()});
            EXPECT_EQ(r.exitCode, 0) << e.path() << "\n" << r.err;
            EXPECT_NE(r.out.find(e.path().filename().string() + ": ok: "), std::string::npos) << r.out;
            ++files;
        }
    EXPECT_GE(files, 3 + 3 + 5 + 5);
}

TEST(ValidateCli, SummaryCountsTheScene) {
    const CliRun r = validate({(kResources / "scenes/ring_on_ground.wlscene").string()});
    EXPECT_NE(r.out.find("scene 'ring_on_ground': 2 objects, 6656 triangles, 2 materials, 1 lights, environment 512x256"),
              std::string::npos)
        << r.out;
}

TEST(ValidateCli, BadUsageExitsTwo) {
    EXPECT_EQ(validate({}).exitCode, 2);
    EXPECT_EQ(validate({"a.wlscene", "b.wlscene"}).exitCode, 2);
    EXPECT_EQ(validate({"--frobnicate", "a.wlscene"}).exitCode, 2);
    const CliRun r = validate({(kResources / "LICENSES.md").string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("unknown file type '.md'"), std::string::npos) << r.err;
}

} // namespace
