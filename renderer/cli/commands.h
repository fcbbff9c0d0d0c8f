// The wavelit-cli subcommands (architecture.md §6). Each takes the arguments after its name and returns
// the process exit code: 0 success, 1 bad input, 2 bad usage.
#pragma once

#include <string>
#include <vector>

namespace wavelit::cli {

int runRender(const std::vector<std::string>& args);   // render_command.cpp
int runMerge(const std::vector<std::string>& args);    // merge_command.cpp
int runValidate(const std::vector<std::string>& args); // validate_command.cpp
int runWavelet(const std::vector<std::string>& args);  // wavelet_command.cpp
int runBench(const std::vector<std::string>& args);    // bench_command.cpp
int runMix(const std::vector<std::string>& args);      // mix_command.cpp
int runRelight(const std::vector<std::string>& args);  // relight_command.cpp
int runExtractSun(const std::vector<std::string>& args); // extract_sun_command.cpp

} // namespace wavelit::cli
