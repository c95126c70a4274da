// EnvironmentCapture renders a scene of known colours into every map type with both fills; the maps
// hold the right colour in the right direction (guard bands included), and the GLSL lookups read them
// back right. The scene: a box room with one colour per wall around an off-origin capture point, and
// small targets in front of the walls on the seams, drawn by a callback with a tiny shader of its own.
#include "render/passes/EnvironmentCapture.hpp"
#include "support/Directions.hpp"
#include "support/GlTest.hpp"
#include "support/GlslRunner.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <optional>

namespace speculum::test {
namespace {

using namespace render::envmap;

const glm::dvec3 kOrigin(30.0, -4.0, 12.0); // the capture point, in world space
const glm::dvec3 kRoomCentre = kOrigin + glm::dvec3(0.5, 0.3, -0.2);
constexpr double kRoomHalf = 6.0;

struct Target {
    glm::dvec3 direction; // from the capture point
    double distance;
    double half; // half size of the square, facing the capture point
    glm::dvec3 color;
};

// On the paraboloid equator, on the tennis-ball seam and branch cut, at a cube corner, and plain.
const Target kTargets[] = {
    {glm::normalize(glm::dvec3(0.5, -0.3, -1.0)), 2.0, 0.3, {1.0, 0.5, 0.0}},
    {glm::normalize(glm::dvec3(1.0, 0.05, 0.02)), 3.0, 0.8, {1.0, 1.0, 1.0}},
    {glm::normalize(glm::dvec3(-0.5, 0.75, 0.4)), 2.5, 0.6, {0.5, 0.0, 1.0}},
    {glm::normalize(glm::dvec3(1.0, 1.0, 1.0)), 2.0, 0.5, {0.25, 0.25, 0.25}},
    {glm::normalize(glm::dvec3(0.0, 0.3, -1.0)), 3.0, 0.4, {0.0, 0.5, 0.5}},
};

// Wall colours by the cube face index of the wall's normal direction (+X −X +Y −Y +Z −Z).
const glm::dvec3 kWallColors[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};

void targetFrame(const Target& t, glm::dvec3& u, glm::dvec3& v) {
    const glm::dvec3 helper = std::abs(t.direction.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    u = glm::normalize(glm::cross(helper, t.direction));
    v = glm::cross(t.direction, u);
}

// The colour seen from the capture point in world direction d: ray casting the same scene.
glm::dvec3 expectedColor(const glm::dvec3& direction) {
    const glm::dvec3 d = glm::normalize(direction);
    double nearest = 1e30;
    std::optional<glm::dvec3> color;
    for (const Target& t : kTargets) {
        const double facing = glm::dot(d, t.direction);
        if (facing <= 0.0)
            continue;
        const double s = t.distance / facing; // the square's plane: dot(p, direction) = distance
        glm::dvec3 u, v;
        targetFrame(t, u, v);
        const glm::dvec3 p = s * d - t.distance * t.direction;
        if (std::abs(glm::dot(p, u)) <= t.half && std::abs(glm::dot(p, v)) <= t.half && s < nearest) {
            nearest = s;
            color = t.color;
        }
    }
    if (color)
        return *color;
    // The room: the first wall the ray leaves through.
    const glm::dvec3 o = kOrigin - kRoomCentre;
    double best = 1e30;
    int wall = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0)
            continue;
        const double t = ((d[axis] > 0 ? kRoomHalf : -kRoomHalf) - o[axis]) / d[axis];
        if (t < best) {
            best = t;
            wall = 2 * axis + (d[axis] > 0 ? 0 : 1);
        }
    }
    return kWallColors[wall];
}

// Whether every direction within `margin` radians of d sees the same colour as d.
bool awayFromEdges(const glm::dvec3& d, double margin) {
    const glm::dvec3 c = expectedColor(d);
    const glm::dvec3 helper = std::abs(d.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(d, helper));
    const glm::dvec3 v = glm::cross(d, u);
    for (int k = 0; k < 12; ++k) {
        const double a = 2.0 * 3.14159265358979 * k / 12.0;
        for (double r : {0.5 * margin, margin})
            if (expectedColor(d + r * (std::cos(a) * u + std::sin(a) * v)) != c)
                return false;
    }
    return true;
}

struct Vertex {
    glm::vec3 position; // relative to the capture point
    glm::vec3 color;
};

// A square subdivided k×k, wound counter-clockwise as seen from the capture point.
void addSquare(std::vector<Vertex>& out, const glm::dvec3& centre, const glm::dvec3& u, const glm::dvec3& v,
               double half, const glm::dvec3& color, int k) {
    auto at = [&](int i, int j) {
        const double a = -half + 2.0 * half * i / k;
        const double b = -half + 2.0 * half * j / k;
        return Vertex{glm::vec3(centre + a * u + b * v - kOrigin), glm::vec3(color)};
    };
    // Orient so that (u, v) turn counter-clockwise seen from the capture point: u × v points at it.
    const bool flip = glm::dot(glm::cross(u, v), kOrigin - centre) < 0.0;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            Vertex a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if (flip)
                std::swap(b, d);
            out.insert(out.end(), {a, b, c, a, c, d});
        }
}

std::vector<Vertex> sceneVertices() {
    std::vector<Vertex> v;
    for (int wall = 0; wall < 6; ++wall) {
        const int axis = wall / 2;
        glm::dvec3 n(0.0);
        n[axis] = wall % 2 == 0 ? 1.0 : -1.0;
        glm::dvec3 u(0.0), w(0.0);
        u[(axis + 1) % 3] = 1.0;
        w[(axis + 2) % 3] = 1.0;
        addSquare(v, kRoomCentre + kRoomHalf * n, u, w, kRoomHalf, kWallColors[wall], 24);
    }
    for (const Target& t : kTargets) {
        glm::dvec3 u, w;
        targetFrame(t, u, w);
        addSquare(v, kOrigin + t.distance * t.direction, u, w, t.half, t.color, 8);
    }
    return v;
}

const char* kVertexMain = R"(
in vec3 aPosition;
in vec3 aColor;
uniform mat4 uViewProjection;
uniform int uWarp;
out vec3 vColor;
void main() {
    vColor = aColor;
    gl_Position = uWarp != 0 ? envmapWarp(aPosition) : uViewProjection * vec4(aPosition, 1.0);
}
)";

const char* kFragment = R"(#version 330 core
in vec3 vColor;
out vec4 fragColor;
void main() { fragColor = vec4(vColor, 1.0); }
)";

class EnvMapCapture : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        std::string error;
        m_program = compileProgram(shaderText("envmap_warp.glsl") + kVertexMain, kFragment, error);
        ASSERT_TRUE(m_program) << error;
        ASSERT_TRUE(m_runner.build(error)) << error;
        const std::vector<Vertex> vertices = sceneVertices();
        m_count = GLsizei(vertices.size());
        m_vao = render::gl::makeVertexArray();
        m_buffer = render::gl::makeBuffer();
        glBindVertexArray(m_vao.id());
        glBindBuffer(GL_ARRAY_BUFFER, m_buffer.id());
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
                     GL_STATIC_DRAW);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<void*>(sizeof(glm::vec3)));
        glEnableVertexAttribArray(0);
        glEnableVertexAttribArray(1);
        glBindVertexArray(0);
    }

    void draw(bool warp, const glm::dmat4& viewProjection) {
        glUseProgram(m_program.id());
        glUniform1i(glGetUniformLocation(m_program.id(), "uWarp"), warp ? 1 : 0);
        glUniformMatrix4fv(glGetUniformLocation(m_program.id(), "uViewProjection"), 1, GL_FALSE,
                           glm::value_ptr(glm::mat4(viewProjection)));
        // Back faces culled: a wrong winding (an unflagged mirror image) would lose the whole scene.
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glBindVertexArray(m_vao.id());
        glDrawArrays(GL_TRIANGLES, 0, m_count);
        glBindVertexArray(0);
    }

    EnvironmentCapture capture(MapType type, FillMethod fill, int n) {
        auto capture = EnvironmentCapture::create({type, n, fill});
        EXPECT_TRUE(capture.ok()) << (capture.ok() ? "" : capture.error());
        CaptureView view;
        view.near = 0.05;
        view.far = 30.0;
        view.background = {0.0, 0.0, 0.0};
        int faces = 0, warps = 0;
        capture->update(
            view,
            [&](const glm::dmat4& viewProjection, int) {
                ++faces;
                draw(false, viewProjection);
            },
            [&](const WarpPass& pass) {
                ++warps;
                glUseProgram(m_program.id());
                setWarpUniformsRaw(pass);
                glFrontFace(pass.warp.mirrored ? GL_CW : GL_CCW);
                draw(true, glm::dmat4(1.0));
            });
        EXPECT_EQ(faces, (type == MapType::Cube || fill == FillMethod::Resampled) ? 6 : 0);
        EXPECT_EQ(warps, (type != MapType::Cube && fill == FillMethod::Direct) ? 2 : 0);
        return std::move(*capture);
    }

    // setWarpUniforms needs a gl::Program; the test's program is a raw handle, so set the same uniforms.
    void setWarpUniformsRaw(const WarpPass& pass) {
        const GLuint p = m_program.id();
        glUniform1i(glGetUniformLocation(p, "uEnvWarpType"), int(pass.warp.type));
        glUniform1i(glGetUniformLocation(p, "uEnvWarpComponent"), pass.warp.component);
        glUniformMatrix4fv(glGetUniformLocation(p, "uEnvWarpView"), 1, GL_FALSE,
                           glm::value_ptr(glm::mat4(pass.view)));
        glUniform4fv(glGetUniformLocation(p, "uEnvWarpParams"), 1,
                     glm::value_ptr(glm::vec4(pass.warp.packed())));
        glUniform1f(glGetUniformLocation(p, "uEnvWarpFar"), float(pass.warp.far));
    }

    // Level 0 of every component: faces of a cube, layers of an array.
    static std::vector<glm::vec4> readBack(const EnvironmentCapture& capture) {
        const MapLayout& l = capture.layout();
        std::vector<glm::vec4> texels(std::size_t(l.components) * l.width * l.height);
        glBindTexture(capture.target(), capture.texture());
        if (capture.target() == GL_TEXTURE_CUBE_MAP) {
            for (int face = 0; face < 6; ++face)
                glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, GL_FLOAT,
                              texels.data() + std::size_t(face) * l.width * l.height);
        } else {
            glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA, GL_FLOAT, texels.data());
        }
        glBindTexture(capture.target(), 0);
        return texels;
    }

    void checkMap(MapType type, FillMethod fill, int n) {
        const EnvironmentCapture map = capture(type, fill, n);
        const MapLayout& l = map.layout();
        const std::vector<glm::vec4> texels = readBack(map);
        auto texel = [&](int c, glm::dvec2 st) {
            const int x = std::clamp(int(st.x * l.width), 0, l.width - 1);
            const int y = std::clamp(int(st.y * l.height), 0, l.height - 1);
            return glm::dvec3(texels[(std::size_t(c) * l.height + y) * l.width + x]);
        };
        // Margin: the largest texel angle (paraboloid centre, cube face centre, tennis-ball equator)
        // times 2.5 for filtering, the resampled fill's blur and the warp's curved edges.
        const double texelAngle = type == MapType::Cube             ? 2.0 / n
                                  : type == MapType::DualParaboloid ? 4.0 / (n - 2 * l.guard)
                                                                    : 1.571 / (n - 2 * l.guard);
        const double margin = 2.5 * texelAngle;
        const char* label =
            type == MapType::Cube ? "" : (fill == FillMethod::Direct ? " direct" : " resampled");

        // 1. Directions from the capture point: the texel the lookup reads holds the colour seen there.
        int tested = 0, wrong = 0;
        std::vector<glm::dvec3> lookupDirs;
        for (const glm::dvec3& d : randomDirections(3000, 31)) {
            if (!awayFromEdges(d, margin))
                continue;
            ++tested;
            lookupDirs.push_back(d);
            const MapCoord c = toMap(type, d);
            const glm::dvec3 got = texel(c.component, l.toTexture(c.uv));
            if (glm::length(got - expectedColor(d)) > 0.01 && wrong++ < 5)
                ADD_FAILURE() << mapTypeName(type) << label << ": direction (" << d.x << ", " << d.y << ", "
                              << d.z << ") holds (" << got.r << ", " << got.g << ", " << got.b << ")";
        }
        EXPECT_GT(tested, 1500) << mapTypeName(type);
        EXPECT_EQ(wrong, 0) << mapTypeName(type) << label << ": " << wrong << " of " << tested;

        // 2. The guard band holds the environment continued past each component's square.
        int guardTested = 0, guardWrong = 0;
        for (int c = 0; c < l.components && type != MapType::Cube; ++c)
            for (int y = 0; y < l.height; y += 2)
                for (int x = 0; x < l.width; x += 2) {
                    const bool inGuard =
                        x < l.guard || y < l.guard || x >= l.width - l.guard || y >= l.height - l.guard;
                    if (!inGuard)
                        continue;
                    const glm::dvec2 uv = l.texelCentre(x, y);
                    // The direct fill draws a paraboloid's band only inside the near plane's cone, which
                    // meets the texture's edge at the middle of each side: its corners stay empty.
                    if (type == MapType::DualParaboloid && fill == FillMethod::Direct &&
                        glm::length(uv * 2.0 - 1.0) > 1.0 / l.scale.x - 2.0 / (n - 2 * l.guard))
                        continue;
                    const glm::dvec3 d = fromMap(type, c, uv);
                    if (!awayFromEdges(d, margin))
                        continue;
                    ++guardTested;
                    const glm::dvec3 got = texel(c, glm::dvec2((x + 0.5) / l.width, (y + 0.5) / l.height));
                    if (glm::length(got - expectedColor(d)) > 0.01 && guardWrong++ < 5)
                        ADD_FAILURE()
                            << mapTypeName(type) << label << ": guard texel " << c << " (" << x << ", " << y
                            << ") holds (" << got.r << ", " << got.g << ", " << got.b << ")";
                }
        if (type != MapType::Cube) {
            EXPECT_GT(guardTested, 50) << mapTypeName(type);
            EXPECT_EQ(guardWrong, 0) << mapTypeName(type) << label << ": " << guardWrong << " of "
                                     << guardTested;
        }

        // 3. The GLSL lookups read the captured map (trilinear, explicit gradients of half a texel).
        glActiveTexture(type == MapType::Cube ? GL_TEXTURE2 : GL_TEXTURE1);
        glBindTexture(map.target(), map.texture());
        glActiveTexture(GL_TEXTURE0);
        std::vector<glm::vec4> inputs;
        for (const glm::dvec3& d : lookupDirs)
            inputs.emplace_back(glm::vec3(d), 0.0f);
        const std::vector<glm::vec4> out = m_runner.run(6, int(type), inputs, [&] {
            glUniform4fv(glGetUniformLocation(m_runner.program(), "uLayout"), 1, glm::value_ptr(l.packed()));
            glUniform1f(glGetUniformLocation(m_runner.program(), "uGrad"), float(0.5 * texelAngle));
        });
        int lookupWrong = 0;
        for (std::size_t i = 0; i < lookupDirs.size(); ++i)
            if (glm::length(glm::dvec3(out[i]) - expectedColor(lookupDirs[i])) > 0.01 && lookupWrong++ < 5)
                ADD_FAILURE() << mapTypeName(type) << label << ": lookup in (" << lookupDirs[i].x << ", "
                              << lookupDirs[i].y << ", " << lookupDirs[i].z << ") gives (" << out[i].r << ", "
                              << out[i].g << ", " << out[i].b << ")";
        EXPECT_EQ(lookupWrong, 0) << mapTypeName(type) << label;
        glActiveTexture(type == MapType::Cube ? GL_TEXTURE2 : GL_TEXTURE1);
        glBindTexture(map.target(), 0);
        glActiveTexture(GL_TEXTURE0);
        std::printf("%s%s n=%d: %d directions, %d guard texels checked\n",
                    std::string(mapTypeName(type)).c_str(), label, n, tested, guardTested);
    }

    render::gl::ProgramHandle m_program;
    render::gl::VertexArray m_vao;
    render::gl::Buffer m_buffer;
    GLsizei m_count = 0;
    GlslRunner m_runner;
};

TEST_F(EnvMapCapture, CubeMapHoldsTheSceneInEachDirection) {
    checkMap(MapType::Cube, FillMethod::Resampled, 64);
}

TEST_F(EnvMapCapture, ResampledDualParaboloidHoldsTheSceneInEachDirection) {
    checkMap(MapType::DualParaboloid, FillMethod::Resampled, 128);
}

TEST_F(EnvMapCapture, DirectDualParaboloidHoldsTheSceneInEachDirection) {
    checkMap(MapType::DualParaboloid, FillMethod::Direct, 128);
}

TEST_F(EnvMapCapture, ResampledTennisBallHoldsTheSceneInEachDirection) {
    checkMap(MapType::TennisBall, FillMethod::Resampled, 64);
}

TEST_F(EnvMapCapture, DirectTennisBallHoldsTheSceneInEachDirection) {
    checkMap(MapType::TennisBall, FillMethod::Direct, 64);
}

TEST_F(EnvMapCapture, ResamplingLeavesTheIntermediateCubeIntact) {
    // update() renders the six faces and then resamples them: the cube's faces must still hold the scene
    // afterwards, update after update (resampling once cleared the face still attached to the framebuffer,
    // which showed from the second update on).
    for (MapType type : {MapType::DualParaboloid, MapType::TennisBall}) {
        auto map = EnvironmentCapture::create({type, 32, FillMethod::Resampled});
        ASSERT_TRUE(map.ok()) << map.error();
        CaptureView view;
        view.near = 0.05;
        view.far = 30.0;
        for (int update = 0; update < 3; ++update)
            map->update(view, [&](const glm::dmat4& viewProjection, int) { draw(false, viewProjection); },
                        {});
        ASSERT_NE(map->intermediateCube(), 0u);
        glBindTexture(GL_TEXTURE_CUBE_MAP, map->intermediateCube());
        for (int face = 0; face < 6; ++face) {
            std::vector<glm::vec4> texels(32 * 32);
            glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, GL_FLOAT, texels.data());
            int wrong = 0, tested = 0;
            for (int y = 0; y < 32; y += 3)
                for (int x = 0; x < 32; x += 3) {
                    const glm::dvec3 d = cubeDirection(face, {(x + 0.5) / 32.0, (y + 0.5) / 32.0});
                    if (!awayFromEdges(d, 0.15))
                        continue;
                    ++tested;
                    if (glm::length(glm::dvec3(texels[std::size_t(y) * 32 + x]) - expectedColor(d)) > 0.01)
                        ++wrong;
                }
            EXPECT_GT(tested, 10);
            EXPECT_EQ(wrong, 0) << mapTypeName(type) << " face " << face << ": " << wrong << " of " << tested;
        }
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    }
}

TEST_F(EnvMapCapture, UpdateRestoresTheCallersState) {
    GLint viewport[4] = {3, 4, 50, 60};
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    (void)capture(MapType::DualParaboloid, FillMethod::Direct, 32); // its callback flips the front face
    (void)capture(MapType::TennisBall, FillMethod::Resampled, 32);
    GLint now[4];
    glGetIntegerv(GL_VIEWPORT, now);
    EXPECT_EQ(now[0], 3);
    EXPECT_EQ(now[3], 60);
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_FALSE(glIsEnabled(GL_CULL_FACE));
    GLint front = 0;
    glGetIntegerv(GL_FRONT_FACE, &front);
    EXPECT_EQ(front, GL_CCW);
    GLfloat clear[4];
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    EXPECT_FLOAT_EQ(clear[2], 0.75f);
}

} // namespace
} // namespace speculum::test
