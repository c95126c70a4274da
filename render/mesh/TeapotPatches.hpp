#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

// Newell's teapot control data (see TeapotPatches.cpp). Internal to makeTeapot() and its tests.
namespace speculum::render::teapot {

inline constexpr std::size_t kPatchCount = 32;
inline constexpr std::size_t kControlPointCount = 306;

using ControlPoint = std::array<float, 3>; // x, y, z in Newell's frame (Z up, spout towards +X)

// Each patch is a 4x4 grid of control point numbers, row by row, numbered from 1.
extern const std::array<std::array<std::uint16_t, 16>, kPatchCount> kPatches;
extern const std::array<ControlPoint, kControlPointCount> kControlPoints;

} // namespace speculum::render::teapot
