#pragma once

#include "base/Result.hpp"

#include <cstdint>
#include <filesystem>
#include <string>

namespace speculum::base {

// Only regular files are ever read: a FIFO, a device or /dev/stdin would block the reader (and the
// editor's GUI thread) for good, and a folder is a mistake. The error says what the path is instead, in
// plain words ("it is a FIFO (named pipe), not a regular file"), without the path itself: callers name it.
Status requireRegularFile(const std::filesystem::path& path);

// The whole file, opened without blocking and checked on the opened descriptor (so a path swapped for a
// FIFO after a check still cannot block). Larger than maxBytes is an error rather than a huge allocation.
Result<std::string> readRegularFile(const std::filesystem::path& path,
                                    std::uintmax_t maxBytes = std::uintmax_t(1) << 31);

} // namespace speculum::base
