#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

namespace speculum::render::reference {

// Where a path's random numbers come from: a counter-based hash of (pixel, path index, bounce, dimension)
// rather than a generator with state, so an image is the same whatever thread traced which row, and a
// render with 2N paths repeats the first N paths of a render with N.
struct PathSeed {
    std::uint32_t x = 0;
    std::uint32_t y = 0;
    std::uint32_t path = 0; // the path's number · sub-samples per pixel + the sub-sample's
};

// A uniform number in [0, 1) (53 bits), independent for every distinct argument tuple.
double pathUniform(const PathSeed& seed, std::uint32_t bounce, std::uint32_t dimension);

// One sample of the GGX reflection lobe about `normal` (unit, world) seen from `viewDir` (unit, towards the
// viewer): the unit direction to follow, and its weight G2/G1 (math::visibleNormalWeight). A weight of 0
// means the sample left below the surface and carries nothing.
struct LobeSample {
    glm::dvec3 direction{0.0};
    double weight = 0.0;
};

// Draws the lobe of `roughness` (α = roughness²) with the visible-normal sampler from two uniform numbers.
LobeSample sampleLobe(const glm::dvec3& normal, const glm::dvec3& viewDir, double roughness, double u1,
                      double u2);

} // namespace speculum::render::reference
