#pragma once

#include "base/Result.hpp"

#include <cstdint>

namespace speculum::render {

// The largest still: its linear RGBA float pixels (16 bytes each) must fit in this many bytes. Larger
// sizes are refused before anything is allocated.
inline constexpr std::uint64_t kMaxStillBytes = std::uint64_t(4) << 30;

// Whether a still of this size can be rendered at all: positive, and its pixels within kMaxStillBytes.
// The message names the size. Needs no GL: the CLI, the export dialog and the tracer check before any
// work.
base::Status checkStillSize(int width, int height);

} // namespace speculum::render
