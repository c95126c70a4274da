#pragma once

#include <array>

namespace speculum::render::math {

// The GGX lobe's directional albedo E(μ_v, roughness) (ggxDirectionalAlbedo, F = 1): the share of a uniform
// surround a rough perfect mirror reflects, the rest lost to masking and shadowing. The rasterizer's glossy
// paths weight their blurred reflection by it (a blur alone keeps every bit of the energy: 2–3× too bright
// at roughness 1), as UE4's, Filament's and three.js's split-sum "DFG" term does.
//
// Tabulated once, on kSize × kSize nodes: μ_v = i / (kSize − 1) (the first a hair above 0) and roughness
// = j / (kSize − 1), α = roughness². Each node is the mean of the tracer's own estimator (visible-normal
// samples weighted G2/G1, the height-correlated shadowing) over a Hammersley set, so the table and the
// tracer agree by construction; the shaders read it bilinearly, as at() does.
struct GgxAlbedoTable {
    static constexpr int kSize = 32;
    static constexpr int kSamples = 4096; // per node: the table's own noise stays below 1e-3
    // Row-major by roughness: values[j * kSize + i].
    std::array<float, kSize * kSize> values{};

    // Bilinear between the nodes, clamped to the table.
    double at(double cosThetaV, double roughness) const;
    // Where a node lies: its μ_v and its roughness.
    static double nodeCosine(int i);
    static double nodeRoughness(int j);
};

// The table, computed on first use (a few tens of milliseconds) and shared from then on.
const GgxAlbedoTable& ggxAlbedoTable();

} // namespace speculum::render::math
