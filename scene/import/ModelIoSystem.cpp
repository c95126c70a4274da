#include "scene/import/ModelIoSystem.hpp"

#include "base/Printable.hpp"

#include <assimp/DefaultIOStream.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace speculum::scene::detail {
namespace {

namespace fs = std::filesystem;

// DefaultIOStream's constructor from a FILE* is protected; this only makes it reachable.
class RegularFileStream : public Assimp::DefaultIOStream {
public:
    RegularFileStream(FILE* file, const std::string& name)
        : Assimp::DefaultIOStream(file, name) {}
};

std::string describeMode(mode_t mode) {
    if (S_ISDIR(mode)) {
        return "it is a folder, not a file";
    }
    if (S_ISFIFO(mode)) {
        return "it is a FIFO (named pipe), not a regular file";
    }
    if (S_ISSOCK(mode)) {
        return "it is a socket, not a regular file";
    }
    if (S_ISCHR(mode) || S_ISBLK(mode)) {
        return "it is a device, not a regular file";
    }
    return "it is not a regular file";
}

} // namespace

ModelIoSystem::ModelIoSystem(std::string modelPath)
    : m_modelPath(std::move(modelPath)) {}

bool ModelIoSystem::Exists(const char* file) const {
    struct stat info {};
    return file != nullptr && ::stat(file, &info) == 0;
}

Assimp::IOStream* ModelIoSystem::Open(const char* file, const char* mode) {
    if (file == nullptr || mode == nullptr) {
        return nullptr;
    }
    const std::string path(file);
    const auto refuse = [&](const std::string& reason) -> Assimp::IOStream* {
        if (m_refusal.empty()) {
            std::error_code ec;
            const fs::path relative = fs::path(path).lexically_relative(fs::path(m_modelPath).parent_path());
            const bool self = fs::path(path) == fs::path(m_modelPath);
            const std::string shown =
                relative.empty() || *relative.begin() == ".." ? path : relative.string();
            m_refusal = self ? reason : "referenced file " + base::quoted(shown) + ": " + reason;
        }
        return nullptr;
    };
    if (std::strchr(mode, 'w') != nullptr || std::strchr(mode, 'a') != nullptr ||
        std::strchr(mode, '+') != nullptr) {
        return refuse("an import never writes files"); // no reader should ask; refuse if one does
    }
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer before fstat could refuse it.
    const int fd = ::open(file, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        // A missing file is the reader's business (OBJ goes on without its .mtl); nothing to remember.
        return nullptr;
    }
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        const std::string reason = describeMode(info.st_mode);
        ::close(fd);
        return refuse(reason);
    }
    // Regular files never block; clear the flag anyway so that reads behave as they do for fopen.
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    FILE* stream = ::fdopen(fd, "rb");
    if (stream == nullptr) {
        ::close(fd);
        return nullptr;
    }
    return new RegularFileStream(stream, path);
}

} // namespace speculum::scene::detail
