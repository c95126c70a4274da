#pragma once

#include "render/FrameInput.hpp"
#include "render/plan/FramePlan.hpp"

#include <cstdint>
#include <unordered_map>

namespace speculum::render {

// What the renderer kept from earlier frames, as far as planning is concerned.
struct PlannerState {
    // Signature of the contents of each light's shadow map (by index into FrameInput::lights).
    std::unordered_map<int, std::uint64_t> shadowSignatures;
};

inline constexpr int kMaxLights = 8;
inline constexpr int kMaxShadowedLights = 4;

// Hash of everything a light's shadow map depends on: the light, its map settings, the frustum and
// every caster's mesh and transform. Equal signatures mean the old map can be reused.
std::uint64_t shadowSignature(const FrameInput& input, int lightIndex);

// The pure planning step: which passes run this frame, in order, with the reason for each, and which
// effects got no pass and why. Needs no GL.
FramePlan planFrame(const FrameInput& input, const PlannerState& state);

} // namespace speculum::render
