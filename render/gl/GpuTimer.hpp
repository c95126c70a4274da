#pragma once

#include "render/gl/Objects.hpp"

#include <vector>

namespace speculum::render::gl {

// GPU time of consecutive passes from GL_TIMESTAMP queries taken at the boundaries between passes.
// (Timestamps rather than GL_TIME_ELAPSED: llvmpipe reports nonsense for elapsed-time queries that span a
// change of framebuffer, and timestamps need no care about nesting.) A pass that begins where the
// previous one ended shares its timestamp: n back-to-back passes take n + 1 queries, not 2n. That matters
// on llvmpipe, where every query is binned into every tile of the framebuffer and costs a visit to each.
// Results are read at the end of the frame.
class GpuTimer {
public:
    // Marks the start of pass number `index` (0, 1, 2, ... in order).
    void begin(std::size_t index);
    void end();
    // Waits for the results; milliseconds per pass, -1 where no pass was timed. Starts a new frame.
    std::vector<double> collect(std::size_t passCount);

    // Timestamp queries issued since the last collect().
    std::size_t queriesThisFrame() const { return m_used; }

private:
    std::size_t stamp(); // issues a timestamp query, returns its slot

    struct Span {
        std::size_t start = 0;
        std::size_t stop = 0;
        bool timed = false;
    };
    std::vector<Query> m_stamps; // reused from frame to frame
    std::size_t m_used = 0;      // stamps issued this frame
    std::vector<Span> m_spans;   // by pass index
    std::size_t m_current = 0;
    bool m_atBoundary = false; // nothing happened since the last end(): its stamp can start the next pass
};

} // namespace speculum::render::gl
