// Atomic file replacement (architecture.md §6): the bytes go to a temporary file in the destination's
// folder (same file system, so rename is atomic), are flushed and fsync'ed, and only then renamed
// over the target. Any failure removes the temporary and leaves the old file byte-identical; the
// error says which step failed and why (strerror).
#pragma once

#include "util/result.h"

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace wavelit::scene {

// Writes `size` bytes to `fd`; returns the number written or -1 with errno set, like ::write.
// Injectable so tests can simulate a full disk (ENOSPC) where /dev/full cannot be renamed.
using WriteFunction = std::function<long(int fd, const char* data, size_t size)>;

struct AtomicWriteOptions {
    WriteFunction write; // empty: ::write
};

util::Status writeFileAtomic(const std::string& path, std::string_view bytes,
                             const AtomicWriteOptions& options = {});

} // namespace wavelit::scene
