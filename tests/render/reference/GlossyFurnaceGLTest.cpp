// The white furnace: a rough perfect mirror under a uniform white sky reflects exactly the GGX lobe's
// directional albedo E(μ_v, α), the energy masking and shadowing leave. A blur alone would keep all of it
// (1.0 at every roughness: 2–3× too bright at roughness 1). Every raster glossy path (the planar mirror's
// footprint and mip filters, the curved reflector's pre-filtered chain and mip chain) must show E within
// the tracer's noise, at roughness 0.1–1 and views 0–85°; and the table the shaders read agrees with the
// quadrature of the lobe's formulas.
#include "accuracy/run/Furnace.hpp"
#include "render/math/Ggx.hpp"
#include "render/math/GgxAlbedoTable.hpp"
#include "render/reference/Tracer.hpp"
#include "support/GlTest.hpp"

#include <cmath>
#include <cstdio>
#include <glm/trigonometric.hpp>
#include <string>

namespace speculum::test {
namespace {

using render::FrameInput;
using render::GlossyFilter;
namespace reference = render::reference;
namespace math = render::math;

constexpr int kSize = 9; // a small image: the centre pixel is what is measured
constexpr int kCentre = kSize / 2;

// The scenes are the bench's own white furnace (accuracy/run/Furnace.hpp).
FrameInput floorFurnace(double roughness, double viewDegrees) {
    return accuracy::planarFurnace(roughness, viewDegrees);
}

FrameInput ballFurnace(double roughness) {
    return accuracy::reflectorFurnace(roughness);
}

struct Traced {
    glm::dvec3 colour{0.0};
    double noise = 0.0; // the standard error of the pixel's colour
};

Traced traceAt(const FrameInput& input, int width, int height, int x, int y) {
    auto tracer = reference::Tracer::create(input);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error());
    reference::TraceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.samples = 1024;
    auto result = tracer->render(settings);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error());
    if (!result.ok())
        return {};
    const glm::vec4 c = result->image.at(x, y);
    const glm::vec4 n = result->noise.at(x, y);
    return {glm::dvec3(c), std::sqrt(double(n.g))};
}

class GlossyFurnace : public GlTest {
protected:
    glm::dvec3 rasterAt(FrameInput input, GlossyFilter filter, int width, int height, int x, int y) {
        input.settings.glossyFilter = filter;
        const render::Image image = renderImage(input, width, height);
        return image.width == width ? glm::dvec3(image.at(x, y)) : glm::dvec3(-1.0);
    }
};

TEST(GgxAlbedoTable, AgreesWithTheQuadratureOfTheLobe) {
    const math::GgxAlbedoTable& table = math::ggxAlbedoTable();
    double worst = 0.0;
    // The quadrature is exact to 1e-9 from α = 0.04 (roughness 0.2) up; below, E is within 1e-3 of 1.
    for (int j = 7; j < math::GgxAlbedoTable::kSize; j += 3) {
        for (int i = 1; i < math::GgxAlbedoTable::kSize; i += 3) {
            const double roughness = math::GgxAlbedoTable::nodeRoughness(j);
            const double mu = math::GgxAlbedoTable::nodeCosine(i);
            const double exact = math::ggxDirectionalAlbedo(mu, roughness * roughness, 96, 192);
            worst = std::max(
                worst, std::abs(table.values[std::size_t(j * math::GgxAlbedoTable::kSize + i)] - exact));
        }
    }
    std::printf("[ measured ] albedo table against quadrature at its nodes: worst %.2e\n", worst);
    EXPECT_LT(worst, 2e-3);
    // Between the nodes, bilinear reading stays close to the lobe's own value.
    double between = 0.0;
    for (double roughness : {0.1, 0.25, 0.45, 0.7, 1.0})
        for (double degrees : {0.0, 30.0, 60.0, 75.0, 85.0}) {
            const double mu = std::cos(glm::radians(degrees));
            between =
                std::max(between, std::abs(table.at(mu, roughness) -
                                           math::ggxDirectionalAlbedo(mu, roughness * roughness, 96, 192)));
        }
    std::printf("[ measured ] albedo table read between its nodes: worst %.2e\n", between);
    EXPECT_LT(between, 1e-2);
    EXPECT_EQ(table.at(0.5, 0.0), 1.0) << "a perfect mirror loses nothing";
}

const char* filterName(GlossyFilter filter) {
    return filter == GlossyFilter::Mip ? "mip" : filter == GlossyFilter::Chain ? "chain" : "footprint";
}

TEST_F(GlossyFurnace, RoughPlanarMirrorsReflectTheLobesAlbedoWithEveryFilter) {
    for (double roughness : {0.1, 0.3, 0.6, 1.0})
        for (double view : {0.0, 30.0, 60.0, 75.0, 85.0}) {
            const FrameInput input = floorFurnace(roughness, view);
            const Traced exact = traceAt(input, kSize, kSize, kCentre, kCentre);
            const double expected =
                math::ggxDirectionalAlbedo(std::cos(glm::radians(view)), roughness * roughness);
            const std::string at =
                "roughness " + std::to_string(roughness) + ", view " + std::to_string(view);
            SCOPED_TRACE(at);
            // The tracer's own furnace (every view reads the same pixel, so the same random numbers: its
            // deviations from E run together).
            EXPECT_NEAR(exact.colour.g, expected, 4.0 * exact.noise + 1e-3);
            for (GlossyFilter filter : {GlossyFilter::Footprint, GlossyFilter::Mip, GlossyFilter::Chain}) {
                const glm::dvec3 raster = rasterAt(input, filter, kSize, kSize, kCentre, kCentre);
                std::printf(
                    "[ measured ] planar %-9s r %.1f view %2.0f°: raster %.4f, tracer %.4f ± %.4f, E %.4f\n",
                    filterName(filter), roughness, view, raster.g, exact.colour.g, exact.noise, expected);
                // E itself, to the table's reading between its nodes and the half-float buffer.
                EXPECT_NEAR(raster.g, expected, 6e-3) << int(filter);
                EXPECT_NEAR(raster.g, exact.colour.g, 4.0 * exact.noise + 6e-3) << int(filter);
            }
        }
}

TEST_F(GlossyFurnace, RoughReflectorReflectsTheLobesAlbedoWithEitherChain) {
    const int size = 48;
    // The centre faces the camera; the other pixel lies towards the rim, where the view is slanted.
    const int rimX = size / 2 + 13;
    for (double roughness : {0.1, 0.3, 0.6, 1.0}) {
        const FrameInput input = ballFurnace(roughness);
        for (int x : {size / 2, rimX}) {
            const Traced exact = traceAt(input, size, size, x, size / 2);
            SCOPED_TRACE("roughness " + std::to_string(roughness) + ", pixel " + std::to_string(x));
            for (GlossyFilter filter : {GlossyFilter::Footprint, GlossyFilter::Mip, GlossyFilter::Chain}) {
                const glm::dvec3 raster = rasterAt(input, filter, size, size, x, size / 2);
                std::printf("[ measured ] reflector %-9s r %.1f px %d: raster %.4f, tracer %.4f ± %.4f\n",
                            filterName(filter), roughness, x, raster.g, exact.colour.g, exact.noise);
                // The raster pixel's normal is interpolated over a tessellated sphere: a little more slack.
                EXPECT_NEAR(raster.g, exact.colour.g, 4.0 * exact.noise + 1.5e-2) << int(filter);
            }
        }
    }
}

} // namespace
} // namespace speculum::test
