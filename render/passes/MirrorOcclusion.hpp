#pragma once

#include "render/gl/Objects.hpp"
#include "render/plan/FramePlan.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace speculum::render::passes {

// The occlusion tests of the mirror masks, and when the frame waits for them.
//
// Waiting for a mask's result in the middle of a frame makes the driver finish everything drawn so far
// before it can go on (on llvmpipe it ends the scene and starts another: about 0.4 ms of a 1280×720
// frame). The wait only pays when the mirror turns out hidden, so a view whose mask let pixels through
// last frame is drawn without waiting: its reflection is confined to the mask's stencil (or depth-tested
// as a texture), so the image is the same either way, and only the work is lost if it became hidden.
// Its result is read at the start of the next frame, when the GPU has it; a view that was hidden last
// frame, that no frame has seen yet, or whose result was not ready, is waited for, so a hidden mirror
// costs nothing from the frame after it became hidden on.
//
// A texture mirror's mask only counts pixels (its reflection has a texture of its own): where it is not
// waited for, it draws nothing, and the mirror's surface, which is depth-tested against the same scene
// over the same pixels, counts them as it is drawn (countAtSurface).
//
// Views are told apart across frames by the chain of mirrors they are seen through.
class MirrorOcclusion {
public:
    // Collects the results of the previous frame's tests that were not waited for, then gives each view
    // of `plan` a query.
    void beginFrame(const FramePlan& plan);

    // Whether the frame must wait for the view's test before it draws the view's reflection.
    bool mustWait(int view) const;
    GLuint query(int view) const;

    // The result of a test the frame waited for (or, with `anyPassed` unknown, one left for later).
    void waited(int view, bool anyPassed);
    void leftForLater(int view);
    // The view's test is made by its surface's draw, not its mask's: asked by the mask, answered by the
    // surface (which then leaves the result for later).
    void countAtSurface(int view);
    bool countsAtSurface(int view) const;

    // How many tests this frame waited for.
    int waits() const { return m_waits; }

private:
    std::vector<gl::Query> m_queries;                        // one per view of the frame
    std::vector<std::uint64_t> m_keys;                       // per view of the frame
    std::vector<bool> m_atSurface;                           // per view of the frame
    std::unordered_map<std::uint64_t, bool> m_passedBefore;  // by view key: the last result known
    std::vector<std::pair<std::uint64_t, GLuint>> m_pending; // tests not waited for, and their queries
    int m_waits = 0;
};

} // namespace speculum::render::passes
