#include "render/reference/GlossySampling.hpp"

#include "render/math/Ggx.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace speculum::render::reference {

namespace {

// splitmix64's finaliser: a bijection of 64-bit words in which every input bit flips about half the
// output bits.
std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

} // namespace

double pathUniform(const PathSeed& seed, std::uint32_t bounce, std::uint32_t dimension) {
    const std::uint64_t pixel = (std::uint64_t(seed.x) << 32) | seed.y;
    const std::uint64_t counter = (std::uint64_t(seed.path) << 32) | (std::uint64_t(bounce) << 8) | dimension;
    return double(mix(mix(pixel) ^ counter) >> 11) * 0x1.0p-53;
}

LobeSample sampleLobe(const glm::dvec3& normal, const glm::dvec3& viewDir, double roughness, double u1,
                      double u2) {
    // A tangent frame about the normal (Duff et al. 2017, "Building an Orthonormal Basis, Revisited"):
    // continuous everywhere but at one point, and exact for any unit normal.
    const double sign = std::copysign(1.0, normal.z);
    const double a = -1.0 / (sign + normal.z);
    const double b = normal.x * normal.y * a;
    const glm::dvec3 t(1.0 + sign * normal.x * normal.x * a, sign * b, -sign * normal.x);
    const glm::dvec3 s(b, sign + normal.y * normal.y * a, -normal.y);
    const glm::dvec3 v(glm::dot(viewDir, t), glm::dot(viewDir, s), glm::dot(viewDir, normal));
    const double r = std::clamp(roughness, 0.0, 1.0);
    const double alpha = r * r;
    const glm::dvec3 h = math::sampleVisibleNormal(v, alpha, u1, u2);
    const glm::dvec3 l = math::reflectAbout(v, h);
    LobeSample sample;
    sample.weight = math::visibleNormalWeight(v, l, alpha);
    if (sample.weight > 0.0)
        sample.direction = glm::normalize(l.x * t + l.y * s + l.z * normal);
    return sample;
}

} // namespace speculum::render::reference
