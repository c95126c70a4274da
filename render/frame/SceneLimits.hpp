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

// Resolutions, counts and material ranges: the one list the project reader, the inspector, the accuracy
// sweep and the renderers' own assertions take their ranges from (a range written twice drifts apart).
inline constexpr int kMinShadowMapSize = 16; // texels per side; a power of two
inline constexpr int kMaxShadowMapSize = 16384;
// Reflector resolution: texels per cube face or per side of a map's layout.
inline constexpr int kMinEnvironmentMapSize = 8;
inline constexpr int kMaxEnvironmentMapSize = 8192;
inline constexpr int kMinPcfWidth = 1; // shadow filter width in texels; odd
inline constexpr int kMaxPcfWidth = 15;
// Reflections of reflections: the scene's, and the reflector's inside its map.
inline constexpr int kMaxMirrorDepth = 16;
// Curved reflectors seen in each other's maps, each bounce one more map pass per reflector.
inline constexpr int kMaxReflectorBounces = 4;
// Most reflectors given a map in one frame, and most Envmap passes (maps × bounces): past them the
// planner keeps the nearest reflectors' maps and fewer bounces, and says what it left out.
inline constexpr int kMaxReflectorMaps = 16;
inline constexpr int kMaxEnvmapPasses = 48;
inline constexpr int kMinTessellation = 1; // built-in meshes: subdivisions
inline constexpr int kMaxTessellation = 64;
inline constexpr int kMinSsaa = 1; // stills: samples per pixel along each axis
inline constexpr int kMaxSsaa = 16;
inline constexpr int kMinGlossyTaps = 1; // a rough planar mirror's lobe samples per pixel
inline constexpr int kMaxGlossyTaps = 64;
inline constexpr int kMinScreenSteps = 4; // a screen-space mirror's trace: steps through the depth pyramid
inline constexpr int kMaxScreenSteps = 512;
inline constexpr double kMinScreenThickness = 0.001; // what a screen-space ray may pass behind, as a
inline constexpr double kMaxScreenThickness = 1.0;   // share of the surface's view depth
inline constexpr int kMinPrefilterSamples = 1;       // the reflector's pre-filter: lobe samples per texel
inline constexpr int kMaxPrefilterSamples = 1024;
inline constexpr double kMaxShininess = 10000.0; // Blinn-Phong exponent (from 0)
inline constexpr double kMaxNormalScale = 100.0; // normal-map strength, either sign

constexpr bool isPowerOfTwo(int n) {
    return n > 0 && (n & (n - 1)) == 0;
}

} // namespace speculum::render
