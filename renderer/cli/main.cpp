// wavelit-cli: headless rendering, validation and wavelet tools (architecture.md §6).
#include "cli/commands.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

const char* kUsage =
    "usage: wavelit-cli <command> [arguments]\n"
    "commands:\n"
    "  render SCENE -o OUT.exr|png [--spp N] [--time SECONDS] [--sampler NAME]\n"
    "         [--width W --height H] [--seed S] [--bounces B] [--device auto|cpu|vulkan]\n"
    "         [--report REPORT.json] [--also OUT2.exr|png] [--passes FIRST:COUNT] [--mpi]\n"
    "         [--light-groups]   (EXR: beauty R,G,B + one <group>.R,.G,.B layer per light group)\n"
    "  merge PART.exr [PART.exr ...] -o OUT.exr\n"
    "  mix IN.exr -o OUT.exr|png --weights GROUP=W|GROUP=R:G:B[,...] [--exposure EV]\n"
    "  extract-sun SCENE|SETUP.wllight -o OUT.wllight   (the env's sun as a light + a mask)\n"
    "  bench SCENE [--reference REF.exr] [--samplers a,b,..] [--time SECONDS] --out DIR\n"
    "  relight SCENE --edits EDITS.json --out DIR --report R.json [--reference-spp N]\n"
    "         [--width W --height H] [--preview PW] [--level N|auto] [--keep K] [--threads T] [--skip-full-rebuild]\n"
    "         [--coarse-level N [--coarse-stride S] [--first-untruncated-narrow]]\n"
    "  validate FILE\n"
    "  wavelet product A.exr B.exr [C.exr ...] -o OUT.exr [--keep K] [--method dense|sparse]\n"
    "  wavelet sample A.exr [B.exr ...] --count N [--seed S] [--keep K] -o SAMPLES.csv\n"
    "exit codes: 0 success, 1 bad input, 2 bad usage\n";

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    std::string command = argv[1];
    std::vector<std::string> rest(argv + 2, argv + argc);
    if (command == "--help" || command == "-h" || command == "help") {
        std::fputs(kUsage, stdout);
        return 0;
    }
    if (command == "render") return wavelit::cli::runRender(rest);
    if (command == "merge") return wavelit::cli::runMerge(rest);
    if (command == "validate") return wavelit::cli::runValidate(rest);
    if (command == "wavelet") return wavelit::cli::runWavelet(rest);
    if (command == "bench") return wavelit::cli::runBench(rest);
    if (command == "mix") return wavelit::cli::runMix(rest);
    if (command == "relight") return wavelit::cli::runRelight(rest);
    if (command == "extract-sun") return wavelit::cli::runExtractSun(rest);
    std::fprintf(stderr, "wavelit-cli: unknown command '%s'\n%s", command.c_str(), kUsage);
    return 2;
}
