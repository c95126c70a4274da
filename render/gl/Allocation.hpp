#pragma once

#include "base/Result.hpp"
#include "render/plan/GpuLimits.hpp"

#include <cstddef>
#include <epoxy/gl.h>
#include <functional>
#include <string>

namespace speculum::render::gl {

// Checked GPU allocations. A texture, renderbuffer or buffer that does not fit leaves a GL error
// (GL_OUT_OF_MEMORY) and an object every later draw into or from silently ignores: the frame comes out
// unlit or without its reflector. So every allocation of this project runs between beginAllocation()
// and finishAllocation(), render targets are checked for completeness, and the caller falls back to a
// smaller size (SizeFallback) with a warning.

// Tests: any one GL object of more than `bytes` counts as not fitting, without asking the driver, so the
// fallback paths can be seen on any machine. 0 (the default): no such limit.
void setAllocationLimitForTesting(std::size_t bytes);
std::size_t allocationLimitForTesting();

// Drains the errors earlier calls left (so they are not blamed on this allocation) and says whether an
// object of `bytes` may be asked for at all (the test limit above).
base::Status beginAllocation(std::size_t bytes);
// The errors raised since beginAllocation(): GL_OUT_OF_MEMORY reads "did not fit in GPU memory".
base::Status finishAllocation();
// The bound framebuffer's completeness: "the driver cannot draw into it (framebuffer incomplete, status
// 0x8cd6)".
base::Status checkFramebuffer(GLenum target = GL_FRAMEBUFFER);

// True between a beginAllocation() that let the allocation go ahead and the finishAllocation() that
// checks it: GL errors raised then are expected and handled (the tests' KHR_debug check,
// tests/support/DebugOutput, does not count them as errors).
bool allocationBeingChecked();

// What allocating a map the frame planned found.
enum class PlannedAllocation {
    Done,     // the map is there, at the planned size
    FellBack, // the planned size failed: the largest that works (or that none does) is remembered for the
              // next frame's plan; this frame has no map
    Failed,   // another error (warned): no map, and a map of another size would not help
};

// Chooses the largest size, from the one asked for down by halving, whose allocation works, and remembers
// the sizes that failed, so a huge allocation that did not fit is not tried again every frame: the planner
// plans below them (MapLimits). One SizeFallback per kind of map (MapKind), kept as long as the context.
class SizeFallback {
public:
    struct Fitted {
        int size = 0;       // the size allocated; 0 if even `minimum` failed
        std::string reason; // why the first size tried (requested or remembered) failed, if it did
    };
    // Calls allocate(size) for the requested size, or the largest half of it below every size that
    // failed before (belowFailure), then halves after each failure down to `minimum`. allocate() must
    // leave nothing behind when it fails.
    Fitted fit(int requested, int minimum, const std::function<base::Status(int)>& allocate);
    // The smallest size that failed (kNoFailedSize: none), and why.
    int failedAt() const { return m_failed.size; }
    const FailedAllocation& failed() const { return m_failed; }

private:
    FailedAllocation m_failed;
};

} // namespace speculum::render::gl
