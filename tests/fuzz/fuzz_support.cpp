#include "fuzz_support.h"

#include "scene/image_io.h"
#include "scene/load_guard.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace wavelit::fuzz {

namespace fs = std::filesystem;

namespace {

fs::path g_root;

void removeTree() {
    std::error_code ec;
    if (!g_root.empty()) fs::remove_all(g_root, ec);
}

void writeFile(const fs::path& p, const std::string& bytes) {
    fs::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) finding("cannot write " + p.string());
}

// Two triangles, the shape of resources/meshes/quad.obj in 6 lines.
const char* kQuadObj = "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nvn 0 1 0\nf 1//1 3//1 2//1\nf 1//1 4//1 3//1\n";

fs::path makeTree() {
    // /dev/shm keeps the per-input file writes off the disk when it exists.
    std::string base = fs::is_directory("/dev/shm") ? "/dev/shm" : fs::temp_directory_path().string();
    std::string templ = base + "/wavelit_fuzz_XXXXXX";
    if (!mkdtemp(templ.data())) finding("mkdtemp failed in " + base);
    g_root = templ;
    std::atexit(removeTree);

    const fs::path resources = WAVELIT_RESOURCE_DIR, bad = fs::path(WAVELIT_TEST_DATA_DIR) / "bad";
    const fs::path data = g_root / "tests" / "data", input = data / "bad";
    fs::create_directories(input);
    writeFile(g_root / "resources" / "meshes" / "quad.obj", kQuadObj);
    for (const auto& e : fs::directory_iterator(resources / "meshes"))
        writeFile(data / "meshes" / e.path().filename(), kQuadObj);
    fs::create_directories(data / "envmaps");
    util::ImageRGB env(4, 2);
    for (size_t i = 0; i < env.pixels.size(); ++i) env.pixels[i] = glm::vec3(0.25f * float(i % 4), 0.5f, 1.0f);
    for (const auto& e : fs::directory_iterator(resources / "envmaps"))
        if (auto s = scene::writeExr((data / "envmaps" / e.path().filename()).string(), env); !s)
            finding(s.error().message());
    fs::create_directories(data / "lighting");
    for (const auto& e : fs::directory_iterator(resources / "lighting"))
        fs::copy_file(e.path(), data / "lighting" / e.path().filename());
    // The bad corpus's small files, so its scenes find the files they name (cyclic_b.wlscene,
    // bad_light_type.wllight, nan_vertex.obj, nan_texels.exr, ...).
    for (const auto& e : fs::directory_iterator(bad))
        if (e.is_regular_file() && e.file_size() <= 4096 && e.path().extension() != ".md")
            fs::copy_file(e.path(), input / e.path().filename());
    return input;
}

} // namespace

const std::string& inputFolder() {
    static const std::string folder = makeTree().string();
    return folder;
}

std::string writeInput(const uint8_t* data, size_t size, const std::string& name) {
    const std::string path = inputFolder() + "/" + name;
    writeFile(path, std::string(reinterpret_cast<const char*>(data), size));
    return path;
}

void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

void checkError(const util::Error& error, const std::string& path) {
    const std::string message = error.message();
    if (message.find(path) == std::string::npos && message.find(fs::path(path).filename().string()) == std::string::npos)
        finding("the error does not name the file " + path + ": " + message);
    // The guard's count, not its message: libFuzzer learns strings the code compares with and
    // writes them into inputs, which the errors then quote.
    static unsigned long long seen = 0;
    if (scene::unexpectedLoadFailures() != seen) finding("an exception escaped the loader's checks: " + message);
}

} // namespace wavelit::fuzz
