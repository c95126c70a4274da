#pragma once

#include "render/plan/FramePlan.hpp"

#include <cstddef>
#include <glm/vec4.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::render {

// GPU memory of the render targets a frame used, from their sizes and internal formats (24-bit depth
// counts 4 bytes). The caller's own target (the window, or the still's buffer) is not included.
struct TargetMemory {
    std::size_t main = 0;    // the linear colour buffer and its depth-stencil buffer
    std::size_t mirrors = 0; // reflection textures of texture-technique mirrors (mip chains included)
    std::size_t shadows = 0; // depth maps of the lights the main pass samples
    std::size_t envmap = 0;  // the reflectors' maps, depths, intermediate cubes and bounce-before maps
    std::size_t total() const { return main + mirrors + shadows + envmap; }
};

// One planned pass that ran: what execution found and what it cost.
struct PassRun {
    int pass = -1;       // index into FrameReport::plan.passes
    std::string outcome; // what running it found ("waited for its occlusion test"); empty: nothing to add
    double gpuMs = -1.0; // < 0: no GPU timing was available
    double cpuMs = 0.0;
};

// What a pass left at the probed pixel (RenderOptions::probePixel), read back right after it ran.
struct PixelProbe {
    int run = -1; // index into FrameReport::ran
    // The pass wrote a buffer the size of the camera's (its colour buffer, a reflection texture, the
    // output), so the pixel has a value there; false for a map of its own (a shadow or environment map).
    bool readable = false;
    glm::vec4 colour{0.0f}; // linear: what the buffer holds there (an 8-bit sRGB buffer's value decoded)
    int stencil = -1;       // the stencil value there (-1: the buffer has none)
    float depth = -1.0f;    // window depth there, 0..1 (-1: the buffer has none)
    int x = -1;             // the pixel read, in the buffer's GL window coordinates (rows from the bottom)
    int y = -1;
};

// What a frame did: the plan as the planner made it (execution never edits it), the passes that ran in
// order with their outcomes and timings, and every effect that got no pass, the plan's skips first, then
// those execution found (a mirror fully occluded, a map that could not be allocated).
struct FrameReport {
    FramePlan plan;
    std::vector<PassRun> ran;
    std::vector<SkippedEffect> skipped;
    double cpuMs = 0.0;  // whole frame on the CPU, planning included
    double gpuMs = -1.0; // sum of the passes' GPU times, -1 if not measured
    // e.g. a texture that failed to load, or a map drawn smaller than asked because it did not fit in GPU
    // memory ("light 'Lamp': the 8192² cube shadow map did not fit in GPU memory; using 4096²")
    std::vector<std::string> warnings;
    // Non-empty: the frame could not be drawn at all (its colour buffer did not fit); also a warning.
    std::string error;
    // A map failed to allocate at the size planned, one never tried before: the frame went without it (see
    // `skipped` and `warnings`), and the next frame, planned with the size found to work, draws it. A still
    // draws such a frame again; the editor's viewport draws another.
    bool drawAgain = false;
    // A time-sliced map drew one face and others still show an older scene: the next frame draws another.
    // The editor's viewport asks for it; a still does not (an exported frame shows the map as it stands).
    bool mapSettling = false;
    TargetMemory memory;
    // The size the frame was drawn at: the target's, or less with RenderOptions::resolutionScale (then
    // scaled up to the target).
    int drawnWidth = 0;
    int drawnHeight = 0;
    // Mirror masks whose occlusion test the frame waited for before drawing on (passes/MirrorOcclusion):
    // those no earlier frame saw, or saw hidden.
    int occlusionWaits = 0;
    // With RenderOptions::probePixel: one probe per pass that ran, in order. Empty otherwise.
    std::vector<PixelProbe> probes;

    const PlannedPass& planned(const PassRun& run) const {
        return plan.passes[static_cast<std::size_t>(run.pass)];
    }
    // The plan's reason for the pass, then what running it found: "…; waited for its occlusion test".
    std::string reason(const PassRun& run) const {
        const PlannedPass& pass = planned(run);
        return run.outcome.empty() ? pass.reason() : pass.reason() + "; " + run.outcome;
    }
    // How many passes of this kind ran (for `target` only, when given).
    std::size_t countRan(PassKind kind, std::string_view target = {}) const {
        std::size_t n = 0;
        for (const PassRun& run : ran)
            if (planned(run).kind == kind && (target.empty() || planned(run).target == target))
                ++n;
        return n;
    }
};

} // namespace speculum::render
