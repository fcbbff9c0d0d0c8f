// wavelit-make-measured-brdf: writes a MERL-layout measured BRDF file tabulated from an analytic
// plugin, e.g. the shipped example (resources/brdfs/README.md):
//   wavelit-make-measured-brdf OUT.binary glossy 0.9,0.6,0.3 0.5 [thetaH thetaD phiD]
// Exit codes as wavelit-cli: 0 written, 1 the file could not be written, 2 bad usage.
#include "plugins/brdf.h"
#include "plugins/brdf_table.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

int main(int argc, char** argv) {
    using namespace wavelit::plugins;
    if (argc != 5 && argc != 8) {
        std::fprintf(stderr, "usage: %s OUT.binary BRDF R,G,B ROUGHNESS [THETA_H THETA_D PHI_D]\n", argv[0]);
        return 2;
    }
    const Brdf* brdf = findBrdf(argv[2]);
    float r, g, b;
    if (!brdf || std::sscanf(argv[3], "%f,%f,%f", &r, &g, &b) != 3) {
        std::fprintf(stderr, "%s: unknown BRDF '%s' or colour '%s' (want R,G,B)\n", argv[0], argv[2], argv[3]);
        return 2;
    }
    const float roughness = std::strtof(argv[4], nullptr);
    int bins[3] = {90, 90, 180};
    if (argc == 8)
        for (int i = 0; i < 3; ++i) bins[i] = std::atoi(argv[5 + i]);
    if (bins[0] < 1 || bins[1] < 1 || bins[2] < 1) {
        std::fprintf(stderr, "%s: bin counts must be positive\n", argv[0]);
        return 2;
    }
    const std::vector<char> bytes =
        tabulateMerlBrdf(*brdf, BrdfParams(glm::vec3(r, g, b), roughness), bins[0], bins[1], bins[2]);
    std::ofstream out(argv[1], std::ios::binary);
    if (!out.write(bytes.data(), std::streamsize(bytes.size())) || !out.flush()) {
        std::fprintf(stderr, "%s: cannot write\n", argv[1]);
        return 1;
    }
    std::printf("%s: %s r=%g colour %g,%g,%g at %d x %d x %d bins, %zu bytes\n", argv[1], argv[2],
                double(roughness), double(r), double(g), double(b), bins[0], bins[1], bins[2], bytes.size());
    return 0;
}
