#include "base/AtomicFile.hpp"

#include "base/Printable.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <pthread.h>
#include <random>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>
#include <utility>

namespace speculum::base {

namespace {

std::string folderOf(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) {
        return ".";
    }
    return slash == 0 ? std::string("/") : path.substr(0, slash);
}

std::string fileNameOf(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The file rename() must replace: a symbolic link is followed, as an editor saving through a link
// would be expected to (the link itself stays a link).
std::string destinationFor(const std::string& target) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
        char resolved[PATH_MAX];
        if (::realpath(target.c_str(), resolved) != nullptr) {
            return resolved;
        }
    }
    return target;
}

// A rename over a device, a FIFO or a socket would replace the special file itself (as root, /dev/full
// or /dev/null would become a regular file): only a regular file, or nothing, is ever replaced.
std::string notReplaceable(const std::string& destination) {
    struct stat st {};
    if (::stat(destination.c_str(), &st) != 0) {
        return {};
    }
    if (S_ISDIR(st.st_mode)) {
        return "a folder of that name exists";
    }
    if (S_ISFIFO(st.st_mode)) {
        return "it is a FIFO (named pipe), not a regular file";
    }
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) {
        return "it is a device, not a regular file";
    }
    if (S_ISSOCK(st.st_mode)) {
        return "it is a socket, not a regular file";
    }
    return {};
}

bool exists(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0;
}

std::string failureMessage(const std::string& target, const std::string& destination,
                           const std::string& reason) {
    return printable(target, 200) + ": " + reason +
           (exists(destination) ? "; the previous file is unchanged" : "; nothing was written");
}

// ".<name>.tmp-<tag><ext>": hidden, recognisable, and with the real extension last. The name part is
// shortened so the whole stays well under NAME_MAX (255 bytes) even for a target near that limit.
std::string temporaryName(const std::string& destination, unsigned attempt) {
    static std::atomic<unsigned> counter{0};
    static thread_local std::mt19937 random{std::random_device{}()};
    const std::string name = fileNameOf(destination);
    const std::size_t dot = name.find_last_of('.');
    std::string ext = (dot == std::string::npos || dot == 0) ? std::string() : name.substr(dot);
    if (ext.size() > 16) {
        ext.clear();
    }
    char tag[48];
    std::snprintf(tag, sizeof tag, "%x-%x%x%x", static_cast<unsigned>(::getpid()), counter.fetch_add(1),
                  static_cast<unsigned>(random()), attempt);
    const std::string stem = name.substr(0, std::min<std::size_t>(name.size(), 160));
    const std::string folder = folderOf(destination);
    return (folder == "/" ? std::string("/") : folder + "/") + "." + stem + ".tmp-" + tag + ext;
}

// Opens a fresh temporary next to `destination` with O_EXCL; -1 and errno on failure.
int createTemporary(const std::string& destination, std::string& tempPath) {
    for (unsigned attempt = 0; attempt < 64; ++attempt) {
        tempPath = temporaryName(destination, attempt);
        const int fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            // Keep the permissions of the file being replaced (a private project stays private).
            struct stat st {};
            if (::stat(destination.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
                (void)::fchmod(fd, st.st_mode & 07777);
            }
            return fd;
        }
        if (errno != EEXIST) {
            tempPath.clear();
            return -1;
        }
    }
    tempPath.clear();
    errno = EEXIST;
    return -1;
}

// fsync() that treats "this file system cannot sync" (EINVAL on some special file systems) as done.
bool syncDescriptor(int fd) {
    while (::fsync(fd) != 0) {
        if (errno == EINTR) {
            continue;
        }
        return errno == EINVAL || errno == ENOTSUP;
    }
    return true;
}

// close(): on Linux the descriptor is gone even when close reports EINTR, so only other errors count
// (NFS and some FUSE file systems report a failed deferred write here).
bool closeDescriptor(int fd) {
    return ::close(fd) == 0 || errno == EINTR;
}

// Makes the rename durable; a folder that cannot be synced costs durability only, not correctness.
void syncFolder(const std::string& destination) {
    const int fd = ::open(folderOf(destination).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        (void)::fsync(fd);
        ::close(fd);
    }
}

// A writer that opened the file itself reports a full disk in its own words, if at all ("TIFFWriteScanline
// failed writing line y=64"). Its errno is gone by then, so the cause is read off the disk: a file that
// reached the process's file-size limit, or a folder with no free blocks left. Otherwise its own message.
std::string diagnoseFailedWriter(const std::string& temp, const std::string& writerError) {
    struct stat st {};
    rlimit limit{};
    if (::stat(temp.c_str(), &st) == 0 && ::getrlimit(RLIMIT_FSIZE, &limit) == 0 &&
        limit.rlim_cur != RLIM_INFINITY && static_cast<rlim_t>(st.st_size) >= limit.rlim_cur) {
        return describeWriteError(EFBIG);
    }
    struct statvfs disk {};
    if (::statvfs(folderOf(temp).c_str(), &disk) == 0 && disk.f_bavail == 0) {
        return describeWriteError(ENOSPC);
    }
    return writerError;
}

} // namespace

std::string describeWriteError(int error) {
    const char* words = nullptr;
    switch (error) {
    case ENOSPC:
        words = "the disk is full";
        break;
#ifdef EDQUOT
    case EDQUOT:
        words = "the disk quota is used up";
        break;
#endif
    case EFBIG:
        words = "the file is larger than the disk or the process's file-size limit allows";
        break;
    case EROFS:
        words = "the disk is read-only";
        break;
    case EIO:
        words = "the disk reported an input/output error";
        break;
    case EACCES:
    case EPERM:
        words = "no permission to write in that folder";
        break;
    case ENOENT:
        words = "the folder does not exist";
        break;
    case ENOTDIR:
        words = "a part of the folder path is not a folder";
        break;
    case ENAMETOOLONG:
        words = "the file name is too long";
        break;
    case EISDIR:
        words = "a folder of that name exists";
        break;
    default:
        break;
    }
    const std::string system = std::strerror(error);
    return words ? std::string(words) + " (" + system + ")" : system;
}

Result<AtomicFile> AtomicFile::create(const std::string& target) {
    AtomicFile file;
    file.m_target = target;
    file.m_destination = destinationFor(target);
    if (const std::string refused = notReplaceable(file.m_destination); !refused.empty()) {
        return Error{printable(target, 200) + ": " + refused + "; nothing was written"};
    }
    file.m_fd = createTemporary(file.m_destination, file.m_temp);
    if (file.m_fd < 0) {
        return Error{failureMessage(target, file.m_destination, describeWriteError(errno))};
    }
    return file;
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : m_target(std::move(other.m_target))
    , m_destination(std::move(other.m_destination))
    , m_temp(std::exchange(other.m_temp, {}))
    , m_fd(std::exchange(other.m_fd, -1))
    , m_finished(other.m_finished)
    , m_failed(other.m_failed)
    , m_failure(std::move(other.m_failure)) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
    if (this != &other) {
        cancel();
        m_target = std::move(other.m_target);
        m_destination = std::move(other.m_destination);
        m_temp = std::exchange(other.m_temp, {});
        m_fd = std::exchange(other.m_fd, -1);
        m_finished = other.m_finished;
        m_failed = other.m_failed;
        m_failure = std::move(other.m_failure);
    }
    return *this;
}

AtomicFile::~AtomicFile() {
    cancel();
}

void AtomicFile::cancel() {
    if (m_fd >= 0) {
        ::close(m_fd);
        m_fd = -1;
    }
    if (!m_temp.empty()) {
        ::unlink(m_temp.c_str());
        m_temp.clear();
    }
}

Error AtomicFile::fail(int error) {
    cancel();
    m_failed = true;
    m_failure = failureMessage(m_target, m_destination, describeWriteError(error));
    return Error{m_failure};
}

Status AtomicFile::write(const void* data, std::size_t size) {
    if (m_failed) {
        return Error{m_failure};
    }
    if (m_fd < 0) {
        return fail(EBADF);
    }
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = ::write(m_fd, bytes, std::min<std::size_t>(size, std::size_t(1) << 30));
        if (n < 0) {
            if (errno == EINTR) {
                continue;
            }
            return fail(errno);
        }
        if (n == 0) {
            return fail(ENOSPC); // a regular file that takes no bytes has no room left
        }
        bytes += n;
        size -= static_cast<std::size_t>(n);
    }
    return Done{};
}

Status AtomicFile::finish() {
    if (m_failed) {
        return Error{m_failure};
    }
    if (m_finished) {
        return Done{};
    }
    if (m_fd < 0) {
        return fail(EBADF);
    }
    if (!syncDescriptor(m_fd)) {
        return fail(errno);
    }
    const int fd = std::exchange(m_fd, -1);
    if (!closeDescriptor(fd)) {
        return fail(errno);
    }
    m_finished = true;
    return Done{};
}

Status AtomicFile::commit() {
    if (Status finished = finish(); !finished) {
        return finished;
    }
    if (m_temp.empty()) {
        return fail(EBADF);
    }
    if (::rename(m_temp.c_str(), m_destination.c_str()) != 0) {
        return fail(errno);
    }
    m_temp.clear();
    syncFolder(m_destination);
    return Done{};
}

namespace {

// Holds the signals that end a command until the set of files is in place or restored.
class HeldSignals {
public:
    HeldSignals() {
        sigset_t held;
        sigemptyset(&held);
        for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
            sigaddset(&held, signal);
        }
        m_held = ::pthread_sigmask(SIG_BLOCK, &held, &m_before) == 0;
    }
    ~HeldSignals() {
        if (m_held) {
            ::pthread_sigmask(SIG_SETMASK, &m_before, nullptr);
        }
    }
    HeldSignals(const HeldSignals&) = delete;
    HeldSignals& operator=(const HeldSignals&) = delete;

private:
    sigset_t m_before{};
    bool m_held = false;
};

// A hard link to the file at `destination` under a fresh hidden name beside it; empty when there is no
// file or the file system has no hard links.
std::string keepPrevious(const std::string& destination) {
    if (!exists(destination)) {
        return {};
    }
    for (unsigned attempt = 0; attempt < 64; ++attempt) {
        std::string backup = temporaryName(destination, attempt);
        if (::link(destination.c_str(), backup.c_str()) == 0) {
            return backup;
        }
        if (errno != EEXIST) {
            return {};
        }
    }
    return {};
}

} // namespace

Status commitTogether(std::vector<AtomicFile>& files) {
    for (AtomicFile& file : files) {
        if (Status finished = file.finish(); !finished) {
            return finished;
        }
    }
    std::vector<std::string> previous;
    std::vector<bool> existed;
    for (const AtomicFile& file : files) {
        existed.push_back(exists(file.m_destination));
        previous.push_back(keepPrevious(file.m_destination));
    }
    const auto dropBackups = [&] {
        for (const std::string& backup : previous) {
            if (!backup.empty()) {
                ::unlink(backup.c_str());
            }
        }
    };
    HeldSignals held;
    for (std::size_t i = 0; i < files.size(); ++i) {
        AtomicFile& file = files[i];
        if (::rename(file.m_temp.c_str(), file.m_destination.c_str()) == 0) {
            file.m_temp.clear();
            continue;
        }
        const std::string reason = describeWriteError(errno);
        bool restored = true;
        for (std::size_t j = i; j-- > 0;) { // put back what was replaced, newest first
            const std::string& destination = files[j].m_destination;
            if (!previous[j].empty()) {
                restored = ::rename(previous[j].c_str(), destination.c_str()) == 0 && restored;
                previous[j].clear();
            } else if (existed[j]) {
                restored = false;
            } else {
                ::unlink(destination.c_str());
            }
        }
        dropBackups();
        for (AtomicFile& rest : files) {
            rest.cancel();
        }
        return Error{printable(file.m_target, 200) + ": " + reason +
                     (restored ? "; the previous files are unchanged"
                               : "; the files replaced before it could not all be put back")};
    }
    dropBackups();
    for (const AtomicFile& file : files) {
        syncFolder(file.m_destination);
    }
    return Done{};
}

Status writeFileAtomically(const std::string& target, const void* data, std::size_t size) {
    Result<AtomicFile> file = AtomicFile::create(target);
    if (!file) {
        return Error{file.error()};
    }
    if (Status written = file->write(data, size); !written) {
        return written;
    }
    return file->commit();
}

Status writeFileAtomically(const std::string& target, std::string_view bytes) {
    return writeFileAtomically(target, bytes.data(), bytes.size());
}

Result<StagedPath> StagedPath::create(const std::string& target) {
    StagedPath staged;
    staged.m_target = target;
    staged.m_destination = destinationFor(target);
    if (const std::string refused = notReplaceable(staged.m_destination); !refused.empty()) {
        return Error{printable(target, 200) + ": " + refused + "; nothing was written"};
    }
    const int fd = createTemporary(staged.m_destination, staged.m_temp);
    if (fd < 0) {
        return Error{failureMessage(target, staged.m_destination, describeWriteError(errno))};
    }
    ::close(fd);
    return staged;
}

StagedPath::StagedPath(StagedPath&& other) noexcept
    : m_target(std::move(other.m_target))
    , m_destination(std::move(other.m_destination))
    , m_temp(std::exchange(other.m_temp, {})) {}

StagedPath& StagedPath::operator=(StagedPath&& other) noexcept {
    if (this != &other) {
        cancel();
        m_target = std::move(other.m_target);
        m_destination = std::move(other.m_destination);
        m_temp = std::exchange(other.m_temp, {});
    }
    return *this;
}

StagedPath::~StagedPath() {
    cancel();
}

void StagedPath::cancel() {
    if (!m_temp.empty()) {
        ::unlink(m_temp.c_str());
        m_temp.clear();
    }
}

Error StagedPath::failure(const std::string& reason) const {
    return Error{failureMessage(m_target, m_destination, reason)};
}

Status StagedPath::commit(const std::string& writerError) {
    if (m_temp.empty()) {
        return failure(describeWriteError(EBADF));
    }
    if (!writerError.empty()) {
        const std::string reason = diagnoseFailedWriter(m_temp, writerError);
        cancel();
        return failure(reason);
    }
    struct stat st {};
    if (::stat(m_temp.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
        const int error = errno;
        cancel();
        return failure("the writer left no file (" + std::string(std::strerror(error)) + ")");
    }
    if (st.st_size <= 0) {
        cancel();
        return failure("the writer produced an empty file");
    }
    const int fd = ::open(m_temp.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || !syncDescriptor(fd)) {
        const int error = errno;
        if (fd >= 0) {
            ::close(fd);
        }
        cancel();
        return failure(describeWriteError(error));
    }
    ::close(fd);
    // The writer may have created the file anew, with its own mode: keep the replaced file's.
    struct stat previous {};
    if (::stat(m_destination.c_str(), &previous) == 0 && S_ISREG(previous.st_mode)) {
        (void)::chmod(m_temp.c_str(), previous.st_mode & 07777);
    }
    if (::rename(m_temp.c_str(), m_destination.c_str()) != 0) {
        const int error = errno;
        cancel();
        return failure(describeWriteError(error));
    }
    m_temp.clear();
    syncFolder(m_destination);
    return Done{};
}

} // namespace speculum::base
