#pragma once

#include "render/gl/Objects.hpp"

#include <vector>

namespace speculum::render::gl {

// GPU time of consecutive passes from GL_TIMESTAMP queries taken before and after each pass. (Timestamps
// rather than GL_TIME_ELAPSED: llvmpipe reports nonsense for elapsed-time queries that span a change
// of framebuffer, and timestamps need no care about nesting.) Results are read at the end of the frame.
class GpuTimer {
public:
    // Marks the start of pass number `index` (0, 1, 2, ... in order).
    void begin(std::size_t index);
    void end();
    // Waits for the results; milliseconds per pass, -1 where no pass was timed.
    std::vector<double> collect(std::size_t passCount);

private:
    struct Pair {
        Query start;
        Query stop;
        bool used = false;
    };
    std::vector<Pair> m_pairs;
    std::size_t m_current = 0;
};

} // namespace speculum::render::gl
