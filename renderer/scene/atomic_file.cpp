#include "scene/atomic_file.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

util::Error ioError(const std::string& path, const std::string& step, int err) {
    return makeError(ErrorKind::Io, path, step + ": " + std::strerror(err) + " (the existing file is unchanged)");
}

} // namespace

util::Status writeFileAtomic(const std::string& path, std::string_view bytes, const AtomicWriteOptions& options) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    fs::path dir = target.parent_path();
    if (dir.empty()) dir = ".";
    // mkstemp gives a unique name so two saves racing in one folder never share a temporary.
    std::string tmpName = ".";
    tmpName += target.filename().string();
    tmpName += ".XXXXXX";
    std::string tmpl = (dir / tmpName).string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) return ioError(path, "cannot create a temporary file in " + dir.string(), errno);
    auto abandon = [&](const std::string& step, int err) {
        ::close(fd);
        ::unlink(tmpl.c_str());
        return ioError(path, step, err);
    };
    // mkstemp creates 0600; saved documents get the usual 0644 less the umask.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);

    const WriteFunction write = options.write ? options.write : [](int f, const char* d, size_t n) {
        return long(::write(f, d, n));
    };
    size_t done = 0;
    while (done < bytes.size()) {
        const long n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return abandon("cannot write the temporary file", n < 0 ? errno : EIO);
        done += size_t(n);
    }
    if (::fsync(fd) != 0) return abandon("cannot flush the temporary file to disk", errno);
    if (::close(fd) != 0) {
        const int err = errno;
        ::unlink(tmpl.c_str());
        return ioError(path, "cannot close the temporary file", err);
    }
    if (::rename(tmpl.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmpl.c_str());
        return ioError(path, "cannot replace the file", err);
    }
    // fsync the folder so the rename itself survives a crash.
    if (int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY); dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
    return util::okStatus();
}

} // namespace wavelit::scene
