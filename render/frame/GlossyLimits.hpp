#pragma once

#include "render/frame/FrameInput.hpp"

#include <algorithm>

// The ranges of the glossy-reflection settings (Settings::glossyTaps, ::prefilterSamples), shared by the
// project reader, the inspector and the renderer.
namespace speculum::render {

inline constexpr int kMinGlossyTaps = 1; // a rough planar mirror's lobe samples per pixel
inline constexpr int kMaxGlossyTaps = 64;
inline constexpr int kMinPrefilterSamples = 1; // the reflector's pre-filter: lobe samples per texel
inline constexpr int kMaxPrefilterSamples = 1024;

inline int glossyTapCount(const Settings& settings) {
    return std::clamp(settings.glossyTaps, kMinGlossyTaps, kMaxGlossyTaps);
}

inline int prefilterSampleCount(const Settings& settings) {
    return std::clamp(settings.prefilterSamples, kMinPrefilterSamples, kMaxPrefilterSamples);
}

} // namespace speculum::render
