#include "cli/args.h"

#include <charconv>
#include <cstdio>

namespace wavelit::cli {

using util::Error;
using util::ErrorKind;
using util::makeError;

util::Result<Args> Args::parse(const std::vector<std::string>& argv,
                               const std::set<std::string>& valueFlags,
                               const std::set<std::string>& switchFlags) {
    Args args;
    for (size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        if (a.size() > 2 && a.rfind("--", 0) == 0) {
            std::string name = a, inlineValue;
            bool hasInline = false;
            if (auto eq = a.find('='); eq != std::string::npos) {
                name = a.substr(0, eq);
                inlineValue = a.substr(eq + 1);
                hasInline = true;
            }
            if (switchFlags.count(name)) {
                if (hasInline) return makeError(ErrorKind::Usage, "", name + " takes no value");
                args.m_switches.insert(name);
            } else if (valueFlags.count(name)) {
                if (hasInline) {
                    args.m_values[name] = inlineValue;
                } else {
                    if (i + 1 >= argv.size())
                        return makeError(ErrorKind::Usage, "", name + " needs a value");
                    args.m_values[name] = argv[++i];
                }
            } else {
                return makeError(ErrorKind::Usage, "", "unknown option " + name);
            }
        } else if (a == "-o") {
            if (i + 1 >= argv.size()) return makeError(ErrorKind::Usage, "", "-o needs a value");
            if (!valueFlags.count("-o")) return makeError(ErrorKind::Usage, "", "unknown option -o");
            args.m_values["-o"] = argv[++i];
        } else {
            args.m_positional.push_back(a);
        }
    }
    return args;
}

bool Args::has(const std::string& flag) const {
    return m_switches.count(flag) || m_values.count(flag);
}

std::optional<std::string> Args::value(const std::string& flag) const {
    auto it = m_values.find(flag);
    if (it == m_values.end()) return std::nullopt;
    return it->second;
}

namespace {
template <typename T> util::Result<T> parseNumber(const std::string& flag, const std::string& text) {
    T v{};
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size())
        return makeError(ErrorKind::Usage, "", flag + ": '" + text + "' is not a valid number");
    return v;
}
} // namespace

util::Result<int> Args::intValue(const std::string& flag, int fallback, int min, int max) const {
    auto text = value(flag);
    if (!text) return fallback;
    auto v = parseNumber<int>(flag, *text);
    if (!v) return v.error();
    if (*v < min || *v > max)
        return makeError(ErrorKind::Usage, "",
                         flag + " must be in [" + std::to_string(min) + ", " + std::to_string(max) +
                             "], got " + *text);
    return *v;
}

util::Result<uint64_t> Args::uint64Value(const std::string& flag, uint64_t fallback) const {
    auto text = value(flag);
    if (!text) return fallback;
    return parseNumber<uint64_t>(flag, *text);
}

util::Result<double> Args::doubleValue(const std::string& flag, double fallback, double min,
                                       double max) const {
    auto text = value(flag);
    if (!text) return fallback;
    auto v = parseNumber<double>(flag, *text);
    if (!v) return v.error();
    if (!(*v >= min && *v <= max))
        return makeError(ErrorKind::Usage, "", flag + " out of range: " + *text);
    return *v;
}

int reportError(const Error& error) {
    std::fprintf(stderr, "wavelit-cli: %s\n", error.message().c_str());
    return error.kind == ErrorKind::Usage ? 2 : 1;
}

} // namespace wavelit::cli
