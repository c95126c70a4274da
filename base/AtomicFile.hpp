#pragma once

#include "base/Result.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::base {

// Staged writes: every file speculum writes goes through here, so a write that fails half-way (a full
// disk, a quota, a file-size limit, a yanked USB stick) is an error with one line and never replaces the
// previous file with a truncated one, nor leaves a temporary behind.
//
// The new contents go to a temporary file in the target's folder (so the final rename cannot cross file
// systems), created with O_EXCL under a unique name ".<name>.tmp-<tag><ext>" (the real extension kept
// last, for writers that pick a format by name). Every write is checked (short writes resumed, EINTR
// retried), the file is fsync()ed and closed with both checked, and only then renamed over the target;
// the folder is fsync()ed afterwards so the rename itself survives a crash. A temporary is removed on
// any failure and when the object is destroyed without commit(). An existing target's permission bits
// are kept; a symbolic link target is followed (the file it names is replaced, the link stays).
//
// Errors read "<path>: the disk is full (No space left on device); the previous file is unchanged"
// ("; nothing was written" when there was no previous file). The path is escaped with printable().

// Plain words for a write errno: "the disk is full (No space left on device)".
std::string describeWriteError(int error);

class AtomicFile {
public:
    // Creates the temporary next to `target`. Fails (with the message above) when the folder cannot be
    // written.
    static Result<AtomicFile> create(const std::string& target);

    AtomicFile(AtomicFile&& other) noexcept;
    AtomicFile& operator=(AtomicFile&& other) noexcept;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    ~AtomicFile(); // removes the temporary unless committed

    // Appends bytes. After a failure every later call fails too and commit() refuses.
    Status write(const void* data, std::size_t size);
    Status write(std::string_view bytes) { return write(bytes.data(), bytes.size()); }

    // fsync and close, leaving only the rename: for several files that must appear together, finish()
    // them all before the first commit(), so a late error (a full disk seen at fsync or close) stops them
    // all while every target is still untouched.
    Status finish();

    // finish() if not done yet, then rename over the target. On failure the temporary is gone and the
    // target untouched.
    Status commit();

    // Drops the temporary now; the target is untouched.
    void cancel();

    const std::string& target() const { return m_target; }
    const std::string& temporaryPath() const { return m_temp; }

private:
    friend Status commitTogether(std::vector<AtomicFile>& files);
    AtomicFile() = default;
    Error fail(int error);

    std::string m_target;      // as the caller named it: used in messages
    std::string m_destination; // what rename() replaces (the target, or the file a link names)
    std::string m_temp;
    int m_fd = -1;
    bool m_finished = false;
    bool m_failed = false;
    std::string m_failure;
};

// Files that belong together (a .gltf, its .bin and its images) replace their previous versions as one:
// all are finished first, each previous file is kept by a hard link while the new ones are renamed into
// place, and when any rename fails those already renamed are put back (or removed, where there was none
// before), so the folder holds either the whole new set or the whole old one. SIGINT, SIGTERM, SIGHUP and
// SIGQUIT wait until that is settled. The last file is renamed last: list the one that refers to the
// others there. On a file system without hard links a file replaced before the failure cannot be put
// back, and the error says so.
Status commitTogether(std::vector<AtomicFile>& files);

// The whole file in one call.
Status writeFileAtomically(const std::string& target, const void* data, std::size_t size);
Status writeFileAtomically(const std::string& target, std::string_view bytes);

// For a writer that insists on opening the file itself by name (a library that takes a path): the same
// temporary and rename, but the writer fills path() in between. Check the writer's own error state after
// its last call, including its close (OpenImageIO, libpng and libjpeg report a full disk late, or not at
// all), then commit(): it refuses an empty file, fsyncs what the writer left and renames it into place.
// Prefer encoding into memory and AtomicFile where the writer allows it: only that checks every byte.
class StagedPath {
public:
    static Result<StagedPath> create(const std::string& target);

    StagedPath(StagedPath&& other) noexcept;
    StagedPath& operator=(StagedPath&& other) noexcept;
    StagedPath(const StagedPath&) = delete;
    StagedPath& operator=(const StagedPath&) = delete;
    ~StagedPath(); // removes the temporary unless committed

    // Where the writer writes (exists, empty, created O_EXCL so nobody else owns the name).
    const std::string& path() const { return m_temp; }
    const std::string& target() const { return m_target; }

    // `writerError`: the writer's own message when it failed (the commit is then refused and the
    // temporary removed); empty when it reported success.
    Status commit(const std::string& writerError = {});
    void cancel();

    // The message a failed writer's error becomes: "<path>: <reason>; the previous file is unchanged".
    Error failure(const std::string& reason) const;

private:
    StagedPath() = default;

    std::string m_target;
    std::string m_destination;
    std::string m_temp;
};

} // namespace speculum::base
