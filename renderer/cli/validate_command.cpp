// Placeholder until its owner lands the real command: reports Unsupported (exit 1).
#include "cli/commands.h"

#include <cstdio>

namespace wavelit::cli {
int runValidate(const std::vector<std::string>&) {
    std::fprintf(stderr, "wavelit-cli: 'validate' is not implemented yet\n");
    return 1;
}
} // namespace wavelit::cli
