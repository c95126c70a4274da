#include "tools/marble/Marble.hpp"

#include <cassert>
#include <cmath>
#include <vector>

// Bit-exact results across compilers: a fused multiply-add would round differently.
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

namespace speculum::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

// An integer avalanche hash (xorshift-multiply rounds); every input bit affects every output bit.
std::uint32_t mix(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

std::uint32_t hashCell(std::uint32_t seed, std::int64_t ix, std::int64_t iy) {
    return mix(mix(mix(seed) ^ static_cast<std::uint32_t>(ix)) ^ static_cast<std::uint32_t>(iy));
}

// sin() from a polynomial, so results do not depend on the platform's libm. Error < 4e-6.
double portableSin(double x) {
    double turns = x / (2.0 * kPi);
    turns -= std::floor(turns);             // [0, 1)
    double a = (turns - 0.5) * (2.0 * kPi); // [-pi, pi), and sin(x) = -sin(a)
    if (a > 0.5 * kPi) {
        a = kPi - a;
    } else if (a < -0.5 * kPi) {
        a = -kPi - a;
    }
    const double a2 = a * a;
    const double s = a * (1.0 - a2 / 6.0 * (1.0 - a2 / 20.0 * (1.0 - a2 / 42.0 * (1.0 - a2 / 72.0))));
    return -s;
}

// Perlin's quintic fade: C2-continuous, so there are no visible creases at lattice lines.
double fade(double t) {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

// 2D gradient noise on a lattice that wraps every `period` cells, which makes the texture tile.
// Roughly in [-0.7, 0.7]; zero at lattice points.
double gradientNoise(double x, double y, std::int64_t period, std::uint32_t seed) {
    constexpr double d = 0.70710678118654752;
    static const double gradients[8][2] = {{1, 0}, {-1, 0}, {0, 1},  {0, -1},
                                           {d, d}, {-d, d}, {d, -d}, {-d, -d}};

    const double fx = std::floor(x);
    const double fy = std::floor(y);
    const auto ix = static_cast<std::int64_t>(fx);
    const auto iy = static_cast<std::int64_t>(fy);
    const double tx = x - fx;
    const double ty = y - fy;

    auto corner = [&](std::int64_t cx, std::int64_t cy, double dx, double dy) {
        const std::int64_t wx = ((cx % period) + period) % period;
        const std::int64_t wy = ((cy % period) + period) % period;
        const double* g = gradients[hashCell(seed, wx, wy) & 7U];
        return g[0] * dx + g[1] * dy;
    };
    const double n00 = corner(ix, iy, tx, ty);
    const double n10 = corner(ix + 1, iy, tx - 1.0, ty);
    const double n01 = corner(ix, iy + 1, tx, ty - 1.0);
    const double n11 = corner(ix + 1, iy + 1, tx - 1.0, ty - 1.0);
    const double u = fade(tx);
    const double v = fade(ty);
    const double bottom = n00 + u * (n10 - n00);
    const double top = n01 + u * (n11 - n01);
    return bottom + v * (top - bottom);
}

// Perlin's turbulence: a fractal sum of |noise|, each octave twice the frequency and half the weight.
// The creases of |noise| are what make the veins wander and fork. (u, v) are tile coordinates in [0, 1).
double turbulence(double u, double v, int basePeriod, int octaves, std::uint32_t seed) {
    double sum = 0.0;
    double weight = 1.0;
    std::int64_t period = basePeriod;
    for (int o = 0; o < octaves; ++o) {
        const double n = gradientNoise(u * period, v * period, period, seed + 0x9e3779b9U * (o + 1));
        sum += weight * (n < 0.0 ? -n : n);
        weight *= 0.5;
        period *= 2;
    }
    return sum;
}

// Plain fractal sum (no abs) for the soft clouding of the stone.
double fbm(double u, double v, int basePeriod, int octaves, std::uint32_t seed) {
    double sum = 0.0;
    double weight = 1.0;
    std::int64_t period = basePeriod;
    for (int o = 0; o < octaves; ++o) {
        sum += weight * gradientNoise(u * period, v * period, period, seed + 0x85ebca6bU * (o + 1));
        weight *= 0.5;
        period *= 2;
    }
    return sum;
}

double clamp01(double x) {
    return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x);
}

// A vein is where the sine crosses zero; `sharpness` narrows it. Integer powers keep it libm-free.
double veinProfile(double s, int sharpness) {
    const double closeness = 1.0 - (s < 0.0 ? -s : s);
    double p = 1.0;
    for (int i = 0; i < sharpness; ++i) {
        p *= closeness;
    }
    return p;
}

std::uint8_t toByte(double encoded) {
    return static_cast<std::uint8_t>(std::floor(clamp01(encoded) * 255.0 + 0.5));
}

} // namespace

TextureImage generateMarble(int size, std::uint32_t seed) {
    assert(size > 0 && "generateMarble(): size must be positive");

    // Enough octaves that the finest noise cell is about two pixels wide.
    const int basePeriod = 3;
    int octaves = 1;
    while (octaves < 8 && basePeriod * (1 << octaves) * 2 <= size) {
        ++octaves;
    }

    // Colours are mixed in sRGB-encoded space: the texture is authored as an image, not lit light.
    const double stone[3] = {0.945, 0.937, 0.918};
    const double cloud[3] = {0.86, 0.855, 0.85};
    const double vein[3] = {0.42, 0.43, 0.45};

    TextureImage image{size, size, std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size * 4)};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size;
            const double v = (y + 0.5) / size;

            // Main veins: diagonal bands (integer band counts keep the tile seamless) bent by turbulence.
            const double t1 = turbulence(u, v, basePeriod, octaves, seed);
            const double s1 = portableSin(2.0 * kPi * (1.0 * u + 2.0 * v) + 4.0 * t1);
            // Fainter, finer veins crossing the first ones.
            const double t2 = turbulence(u, v, basePeriod + 1, octaves, seed ^ 0x5bd1e995U);
            const double s2 = portableSin(2.0 * kPi * (-2.0 * u + 3.0 * v) + 5.0 * t2);
            // Vein strength varies along each vein, so some fade out as in real stone.
            const double strength = clamp01(0.55 + 1.2 * fbm(u, v, 3, 3, seed ^ 0x68e31da4U));
            const double veins = clamp01(strength * (0.8 * veinProfile(s1, 24) + 0.25 * veinProfile(s1, 4)) +
                                         0.35 * veinProfile(s2, 40));

            // Soft clouding of the white stone.
            const double c = clamp01(0.5 + 0.9 * fbm(u, v, 2, octaves, seed ^ 0x27d4eb2fU));

            std::uint8_t* p = &image.rgba8[(static_cast<std::size_t>(y) * size + x) * 4];
            for (int k = 0; k < 3; ++k) {
                const double base = stone[k] + (cloud[k] - stone[k]) * c;
                p[k] = toByte(base + (vein[k] - base) * veins);
            }
            p[3] = 255;
        }
    }
    return image;
}

} // namespace speculum::render
