#include "base/FileKind.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace speculum::base {
namespace {

Status describeNonRegular(mode_t mode) {
    if (S_ISREG(mode)) {
        return Done{};
    }
    if (S_ISDIR(mode)) {
        return Error{"it is a folder, not a file"};
    }
    if (S_ISFIFO(mode)) {
        return Error{"it is a FIFO (named pipe), not a regular file"};
    }
    if (S_ISSOCK(mode)) {
        return Error{"it is a socket, not a regular file"};
    }
    if (S_ISCHR(mode) || S_ISBLK(mode)) {
        return Error{"it is a device, not a regular file"};
    }
    return Error{"it is not a regular file"};
}

std::string errnoText(int error) {
    if (error == ENOENT || error == ENOTDIR) {
        return "file not found";
    }
    if (error == ELOOP) {
        return "too many levels of symbolic links";
    }
    if (error == ENAMETOOLONG) {
        return "the file name is too long";
    }
    return std::strerror(error);
}

} // namespace

Status requireRegularFile(const std::filesystem::path& path) {
    struct stat info {};
    if (path.empty()) {
        return Error{"no file name"};
    }
    if (::stat(path.c_str(), &info) != 0) {
        return Error{errnoText(errno)};
    }
    return describeNonRegular(info.st_mode);
}

Result<std::string> readRegularFile(const std::filesystem::path& path, std::uintmax_t maxBytes) {
    if (path.empty()) {
        return Error{"no file name"};
    }
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer before fstat could refuse it.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        return Error{errnoText(errno)};
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        return Error{errnoText(errno)};
    }
    if (const Status regular = describeNonRegular(info.st_mode); !regular) {
        return Error{regular.error()};
    }
    if (static_cast<std::uintmax_t>(info.st_size) > maxBytes) {
        return Error{"the file is too large (" + std::to_string(info.st_size) + " bytes)"};
    }
    std::string bytes;
    bytes.reserve(static_cast<std::size_t>(info.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0) {
            if (errno == EINTR) {
                continue;
            }
            return Error{"cannot read: " + errnoText(errno)};
        }
        if (got == 0) {
            break;
        }
        if (bytes.size() + static_cast<std::size_t>(got) > maxBytes) {
            return Error{"the file is too large"};
        }
        bytes.append(buffer, static_cast<std::size_t>(got));
    }
    return bytes;
}

} // namespace speculum::base
