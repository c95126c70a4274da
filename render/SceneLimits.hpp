#pragma once

namespace speculum::render {

// The range of every number a scene may hold, chosen so that all the float arithmetic the GPU and the
// tracer do on them stays finite: a coordinate squared, times an intensity, stays far below FLT_MAX
// (3.4e38), and an inverse scale stays far above the smallest normal float (1.2e-38). Values outside are
// refused by the project reader (with the JSON path) and by the inspector; inside, both renderers must
// draw finite, correct images. README ▸ Limits lists them for users.
inline constexpr double kMaxCoordinate = 1e12; // metres: positions, targets, centres, sizes, heights
inline constexpr double kMinScale = 1e-9;      // |scale| of a transform, and of a node's world transform
inline constexpr double kMaxScale = 1e9;
inline constexpr double kMaxIntensity = 1e9; // light intensity
inline constexpr double kMinPeriod = 1e-3;   // seconds: animation periods
inline constexpr double kMaxPeriod = 1e9;
inline constexpr double kMinNear = 1e-6;        // camera near plane, metres
inline constexpr double kMaxFarNearRatio = 1e6; // depth-buffer precision: beyond it, far objects vanish

} // namespace speculum::render
