// The GLSL mappings, Jacobians, warps and lookups agree with the C++ ones they twin, and GL's own cube
// sampling agrees with the C++ cube convention.
#include "Seams.hpp"
#include "render/envmap/CaptureMath.hpp"
#include "render/envmap/CpuMap.hpp"
#include "render/passes/EnvironmentCapture.hpp"
#include "support/Directions.hpp"
#include "support/GlTest.hpp"
#include "support/GlslRunner.hpp"

#include <glm/gtc/type_ptr.hpp>

namespace speculum::test {
namespace {

using namespace render::envmap;

constexpr MapType kTypes[] = {MapType::Cube, MapType::DualParaboloid, MapType::TennisBall,
                              MapType::Octahedral};

class EnvMapGlsl : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        std::string error;
        ASSERT_TRUE(m_runner.build(error)) << error;
    }
    GlslRunner m_runner;
};

constexpr int kRandomCount = 4096;

// Random directions first, then those on every special line of the maps.
std::vector<glm::dvec3> testDirections() {
    std::vector<glm::dvec3> dirs = randomDirections(kRandomCount, 77);
    const std::vector<glm::dvec3> special = specialDirections();
    dirs.insert(dirs.end(), special.begin(), special.end());
    return dirs;
}

// Whether some nudge of d by `eps` moves it into `component`: d lies on that component's border.
bool nearComponent(MapType type, const glm::dvec3& d, int component, double eps) {
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            glm::dvec3 e = d;
            e[axis] += sign * eps;
            if (mapComponent(type, e) == component)
                return true;
        }
    return false;
}

TEST_F(EnvMapGlsl, DirectionToUvMatchesCpp) {
    const std::vector<glm::dvec3> dirs = testDirections();
    std::vector<glm::vec4> inputs;
    for (const glm::dvec3& d : dirs)
        inputs.emplace_back(glm::vec3(d), 0.0f);
    for (MapType type : kTypes) {
        const std::vector<glm::vec4> out = m_runner.run(0, int(type), inputs);
        double worst = 0.0;
        int borderDisagreements = 0;
        for (std::size_t i = 0; i < dirs.size(); ++i) {
            const int gpu = int(std::lround(out[i].x));
            const int cpu = mapComponent(type, dirs[i]);
            if (gpu != cpu) {
                // Float and double may round a direction on a border to different sides; both are right.
                ASSERT_TRUE(nearComponent(type, glm::dvec3(glm::vec3(dirs[i])), gpu, 1e-6))
                    << mapTypeName(type) << ": component " << gpu << " vs " << cpu;
                borderDisagreements += int(i) < kRandomCount;
            }
            const glm::dvec2 expected = mapUv(type, gpu, glm::dvec3(glm::vec3(dirs[i])));
            worst = std::max(worst, glm::length(glm::dvec2(out[i].y, out[i].z) - expected));
        }
        EXPECT_LE(worst, 1e-5) << mapTypeName(type);
        // Random directions almost never lie that close to a border.
        EXPECT_LT(borderDisagreements, kRandomCount / 100) << mapTypeName(type);
        std::printf("%s: %zu directions, worst uv difference %.2e, %d random ones on a border\n",
                    std::string(mapTypeName(type)).c_str(), dirs.size(), worst, borderDisagreements);
    }
}

TEST_F(EnvMapGlsl, UvToDirectionMatchesCpp) {
    for (MapType type : kTypes) {
        const MapLayout layout = makeLayout(type, 32);
        std::vector<glm::vec4> inputs;
        for (int c = 0; c < layout.components; ++c)
            for (int y = 0; y < layout.height; ++y)
                for (int x = 0; x < layout.width; ++x)
                    inputs.emplace_back(glm::vec2(layout.texelCentre(x, y)), 0.0f, float(c));
        const std::vector<glm::vec4> out = m_runner.run(1, int(type), inputs);
        double worst = 0.0;
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            const glm::dvec3 expected = fromMap(type, int(inputs[i].w), glm::dvec2(inputs[i]));
            worst = std::max(worst, glm::length(glm::dvec3(out[i]) - expected));
        }
        EXPECT_LE(worst, 1e-5) << mapTypeName(type);
    }
}

TEST_F(EnvMapGlsl, JacobianMatchesCpp) {
    const std::vector<glm::dvec3> dirs = randomDirections(4096, 78);
    for (MapType type : {MapType::DualParaboloid, MapType::TennisBall, MapType::Octahedral}) {
        std::vector<glm::vec4> inputs;
        for (const glm::dvec3& d : dirs)
            inputs.emplace_back(glm::vec3(d), float(mapComponent(type, d)));
        const std::vector<glm::vec4> a = m_runner.run(2, int(type), inputs);
        const std::vector<glm::vec4> b = m_runner.run(3, int(type), inputs);
        for (std::size_t i = 0; i < dirs.size(); ++i) {
            const glm::dmat3x2 j = uvJacobian(type, int(inputs[i].w), glm::dvec3(glm::vec3(dirs[i])));
            const double scale = 1.0 + std::max({glm::length(j[0]), glm::length(j[1]), glm::length(j[2])});
            ASSERT_LE(glm::length(glm::dvec2(a[i].x, a[i].y) - j[0]), 1e-5 * scale) << mapTypeName(type);
            ASSERT_LE(glm::length(glm::dvec2(a[i].z, a[i].w) - j[1]), 1e-5 * scale) << mapTypeName(type);
            ASSERT_LE(glm::length(glm::dvec2(b[i].x, b[i].y) - j[2]), 1e-5 * scale) << mapTypeName(type);
        }
    }
}

TEST_F(EnvMapGlsl, WarpMatchesCpp) {
    const std::vector<glm::dvec3> dirs = randomDirections(4096, 79);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> distance(0.2, 15.0);
    for (MapType type : {MapType::DualParaboloid, MapType::TennisBall}) {
        const MapLayout layout = makeLayout(type, 128);
        for (int component = 0; component < 2; ++component) {
            const WarpPass pass{warpParameters(layout, component, 20.0), glm::dmat4(1.0)};
            std::vector<glm::vec4> inputs;
            std::vector<glm::dvec3> positions;
            for (const glm::dvec3& d : dirs)
                if (mapComponent(type, d) == component) {
                    positions.push_back(glm::dvec3(glm::vec3(distance(rng) * d)));
                    inputs.emplace_back(glm::vec3(positions.back()), 0.0f);
                }
            const std::vector<glm::vec4> out = m_runner.run(5, int(type), inputs, [&] {
                const GLuint p = m_runner.program();
                glUniform1i(glGetUniformLocation(p, "uEnvWarpType"), int(type));
                glUniform1i(glGetUniformLocation(p, "uEnvWarpComponent"), component);
                glUniformMatrix4fv(glGetUniformLocation(p, "uEnvWarpView"), 1, GL_FALSE,
                                   glm::value_ptr(glm::mat4(pass.view)));
                glUniform4fv(glGetUniformLocation(p, "uEnvWarpParams"), 1,
                             glm::value_ptr(glm::vec4(pass.warp.packed())));
                glUniform1f(glGetUniformLocation(p, "uEnvWarpFar"), float(pass.warp.far));
            });
            double worst = 0.0;
            for (std::size_t i = 0; i < positions.size(); ++i)
                worst =
                    std::max(worst, glm::length(glm::dvec4(out[i]) - warpVertex(pass.warp, positions[i])));
            EXPECT_LE(worst, 1e-5) << mapTypeName(type) << " component " << component;
        }
    }
}

TEST_F(EnvMapGlsl, GlCubeSamplingFollowsTheCppConvention) {
    // A 16×16 cube whose texels hold (face, x, y), sampled with NEAREST in known directions.
    constexpr int n = 16;
    render::gl::Texture cube = render::gl::makeTexture();
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube.id());
    for (int face = 0; face < 6; ++face) {
        std::vector<glm::vec4> texels;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                texels.emplace_back(float(face), float(x), float(y), 1.0f);
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA32F, n, n, 0, GL_RGBA, GL_FLOAT,
                     texels.data());
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
    glActiveTexture(GL_TEXTURE0);
    std::vector<glm::dvec3> dirs;
    for (const glm::dvec3& d : randomDirections(4000, 80)) {
        const glm::dvec2 t = cubeUv(cubeFace(d), d) * double(n);
        const glm::dvec3 a = glm::abs(d);
        const double second = a.x + a.y + a.z - std::max({a.x, a.y, a.z}) - std::min({a.x, a.y, a.z});
        // Keep away from texel borders and face edges, where NEAREST may go either way.
        if (std::abs(t.x - std::round(t.x)) > 0.05 && std::abs(t.y - std::round(t.y)) > 0.05 &&
            std::max({a.x, a.y, a.z}) - second > 1e-3)
            dirs.push_back(d);
    }
    std::vector<glm::vec4> inputs;
    for (const glm::dvec3& d : dirs)
        inputs.emplace_back(glm::vec3(d), 0.0f);
    const std::vector<glm::vec4> out = m_runner.run(4, int(MapType::Cube), inputs);
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        const int face = cubeFace(dirs[i]);
        const glm::dvec2 t = glm::floor(cubeUv(face, dirs[i]) * double(n));
        ASSERT_EQ(out[i], glm::vec4(float(face), float(t.x), float(t.y), 1.0f)) << "direction " << i;
    }
    EXPECT_GT(dirs.size(), 2500u);
}

// GPU lookups of maps uploaded from CPU: they match the CPU model, and are continuous across every
// seam (the criterion of the unit tier, on the GPU's own filtering), at LOD 0 and at LOD 1.
TEST_F(EnvMapGlsl, LookupsMatchTheCpuModelAndAreSeamless) {
    auto environment = [](const glm::dvec3& d) {
        return 0.5 + 0.5 * glm::dvec3(std::sin(3.0 * d.x + 1.3 * d.y + 0.2),
                                      std::sin(2.5 * d.y - 2.0 * d.z + 0.4),
                                      std::cos(2.0 * d.x + 3.0 * d.z - d.y));
    };
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    const CpuMap reference = CpuMap::fill(makeLayout(MapType::Cube, 256), environment);
    for (MapType type : kTypes) {
        const MapLayout layout = makeLayout(type, 64);
        const CpuMap map = CpuMap::fill(layout, environment);
        // Upload the CPU map and let GL build the mip chain.
        render::gl::Texture texture = render::gl::makeTexture();
        const GLenum target = type == MapType::Cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D_ARRAY;
        glActiveTexture(type == MapType::Cube ? GL_TEXTURE2 : GL_TEXTURE1);
        glBindTexture(target, texture.id());
        std::vector<glm::vec4> texels;
        for (int c = 0; c < layout.components; ++c)
            for (int y = 0; y < layout.height; ++y)
                for (int x = 0; x < layout.width; ++x)
                    texels.emplace_back(glm::vec3(map.texel(c, x, y)), 1.0f);
        if (type == MapType::Cube) {
            for (int face = 0; face < 6; ++face)
                glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA32F, layout.width,
                             layout.height, 0, GL_RGBA, GL_FLOAT,
                             texels.data() + std::size_t(face) * layout.width * layout.height);
        } else {
            glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, layout.width, layout.height, layout.components,
                         0, GL_RGBA, GL_FLOAT, texels.data());
        }
        glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        // As the capture does: an octahedral map's chain stops where its sides leave texel boundaries.
        glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, usableMipLevels(layout) - 1);
        glGenerateMipmap(target);
        glActiveTexture(GL_TEXTURE0);

        const std::vector<SeamPoint> seams = type == MapType::Cube             ? cubeSeams()
                                             : type == MapType::DualParaboloid ? paraboloidSeams()
                                             : type == MapType::TennisBall     ? tennisBallSeams()
                                                                               : octahedralSeams();
        // The largest arc a texel spans (√6 rad per unit of p for the octahedron, p = 2·uv).
        const double span = type == MapType::DualParaboloid ? 4.0
                            : type == MapType::TennisBall   ? 1.571
                                                            : 4.899;
        const double texel = type == MapType::Cube ? 2.0 / 64 : span / (64 - 2 * layout.guard);
        std::vector<glm::vec4> inputs;
        std::vector<glm::dvec3> dirs;
        for (const SeamPoint& s : seams)
            for (double sign : {-1.0, 1.0}) {
                dirs.push_back(glm::normalize(s.point + sign * 0.05 * texel * s.across));
                inputs.emplace_back(glm::vec3(dirs.back()), 0.0f);
            }
        for (float lodTexels : {0.0f, 2.0f}) {
            const std::vector<glm::vec4> out = m_runner.run(6, int(type), inputs, [&] {
                const GLuint p = m_runner.program();
                glUniform4fv(glGetUniformLocation(p, "uLayout"), 1, glm::value_ptr(layout.packed()));
                glUniform1f(glGetUniformLocation(p, "uGrad"), float(lodTexels * texel));
            });
            double worstExcess = -1.0, worstModel = 0.0;
            for (std::size_t i = 0; i + 1 < dirs.size(); i += 2) {
                const double gpuStep = glm::length(glm::dvec3(out[i]) - glm::dvec3(out[i + 1]));
                const double referenceStep =
                    glm::length(reference.lookup(dirs[i]) - reference.lookup(dirs[i + 1]));
                worstExcess = std::max(worstExcess, gpuStep - referenceStep);
                if (lodTexels == 0.0f)
                    worstModel = std::max(worstModel, glm::length(glm::dvec3(out[i]) - map.lookup(dirs[i])));
            }
            // Same tolerance as the unit tier: a tenth of the environment's change over one texel.
            EXPECT_LE(worstExcess, 0.1 * 1.9 * texel * std::sqrt(3.0))
                << mapTypeName(type) << " lod texels " << lodTexels;
            if (lodTexels == 0.0f) {
                // GL averages three faces at a cube corner where the CPU model reads one.
                EXPECT_LE(worstModel, 3e-3) << mapTypeName(type);
            }
            std::printf(
                "%s, footprint %.0f texels: worst seam excess %.2e, worst difference to the CPU model %.2e\n",
                std::string(mapTypeName(type)).c_str(), lodTexels, worstExcess, worstModel);
        }
        glBindTexture(target, 0);
    }
}

} // namespace
} // namespace speculum::test
