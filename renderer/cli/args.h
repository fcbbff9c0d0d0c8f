// A small command-line parser shared by the wavelit-cli subcommands: positional arguments plus
// "--flag value" options, each declared with a type. Unknown flags and missing or malformed values
// are Usage errors (exit code 2).
#pragma once

#include "util/result.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace wavelit::cli {

class Args {
public:
    // valueFlags take one value ("--spp 16"); switchFlags take none ("--quiet").
    static util::Result<Args> parse(const std::vector<std::string>& argv,
                                    const std::set<std::string>& valueFlags,
                                    const std::set<std::string>& switchFlags = {});

    const std::vector<std::string>& positional() const { return m_positional; }
    bool has(const std::string& flag) const;
    std::optional<std::string> value(const std::string& flag) const;
    util::Result<int> intValue(const std::string& flag, int fallback, int min, int max) const;
    util::Result<uint64_t> uint64Value(const std::string& flag, uint64_t fallback) const;
    util::Result<double> doubleValue(const std::string& flag, double fallback, double min,
                                     double max) const;

private:
    std::vector<std::string> m_positional;
    std::map<std::string, std::string> m_values;
    std::set<std::string> m_switches;
};

// Prints "wavelit-cli: <message>" to stderr and returns the exit code for the error's kind
// (Usage -> 2, everything else -> 1), as architecture.md §6 fixes.
int reportError(const util::Error& error);

} // namespace wavelit::cli
