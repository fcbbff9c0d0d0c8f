#include "util/result.h"

namespace wavelit::util {

const char* errorKindName(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::NotFound: return "not found";
    case ErrorKind::Io: return "I/O error";
    case ErrorKind::Format: return "format error";
    case ErrorKind::Invalid: return "invalid";
    case ErrorKind::Unsupported: return "unsupported";
    case ErrorKind::Device: return "device error";
    case ErrorKind::Usage: return "usage";
    }
    return "error";
}

std::string Error::message() const {
    std::string out;
    if (!file.empty()) out += file;
    if (!where.empty()) out += (out.empty() ? "" : ":") + where;
    if (!out.empty()) out += ": ";
    out += reason;
    return out;
}

} // namespace wavelit::util
