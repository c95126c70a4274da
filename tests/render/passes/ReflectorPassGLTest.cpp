// The curved reflector rendered end to end (pass 1 and pass 2): a mirror ball in a room of six emissive
// walls of known colours shows, at each pixel, the wall its reflection vector points at, for every map
// type and both fills. And a static scene renders its environment map once.
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"
#include "support/GlTest.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <optional>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 256;
constexpr int kHeight = 256;
constexpr double kRoomHalf = 20.0; // large against the ball: the capture point's offset barely matters
constexpr double kRadius = 1.0;

// Wall colours by the axis direction of the wall (+X −X +Y −Y +Z −Z).
const glm::dvec3 kWallColors[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};

Material emissive(glm::dvec3 color) {
    Material m;
    m.color = {0.0, 0.0, 0.0};
    m.ambient = 0.0;
    m.diffuse = 0.0;
    m.emission = color;
    return m;
}

FrameInput ballInRoom(ReflectorMap map, ReflectorFill fill) {
    FrameInput input;
    input.settings.background = {0.0, 0.0, 0.0};
    input.settings.ambient = 0.0;
    input.camera.position = {0.0, 0.0, 3.2};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 45.0;
    input.camera.far = 100.0;
    static const auto plane = std::make_shared<const MeshData>(makePlane(1));
    for (int wall = 0; wall < 6; ++wall) {
        const int axis = wall / 2;
        glm::dvec3 n(0.0);
        n[axis] = wall % 2 == 0 ? 1.0 : -1.0;
        // The unit plane faces +Y; turn +Y onto the wall's axis (two-sided and emissive: facing is moot).
        glm::dmat4 turn(1.0);
        if (axis == 0)
            turn = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 0, 1));
        else if (axis == 2)
            turn = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0));
        const glm::dmat4 world = glm::translate(glm::dmat4(1.0), n * kRoomHalf) * turn *
                                 glm::scale(glm::dmat4(1.0), glm::dvec3(kRoomHalf));
        input.items.push_back(
            {"Wall " + std::to_string(wall), world, plane, emissive(kWallColors[wall]), false});
    }
    Reflector r;
    r.name = "Ball";
    r.mesh = std::make_shared<const MeshData>(makeSphere(96));
    r.world = glm::scale(glm::dmat4(1.0), glm::dvec3(kRadius));
    r.material = emissive({0.0, 0.0, 0.0});
    r.reflectivity = 1.0;
    r.map = map;
    r.fill = fill;
    r.resolution = 128;
    input.reflectors = {r};
    return input;
}

// The wall a direction from the ball's centre points at.
int wallOf(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return 2 * axis + (d[axis] > 0.0 ? 0 : 1);
}

// Whether every direction within `margin` radians of d points at the same wall.
bool awayFromEdges(const glm::dvec3& d, double margin) {
    const int wall = wallOf(d);
    const glm::dvec3 helper = std::abs(d.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(d, helper));
    const glm::dvec3 v = glm::cross(d, u);
    for (int k = 0; k < 16; ++k) {
        const double a = 2.0 * 3.14159265358979 * k / 16.0;
        if (wallOf(d + margin * (std::cos(a) * u + std::sin(a) * v)) != wall)
            return false;
    }
    return true;
}

struct Check {
    int checked = 0;
    int wrong = 0;
    std::string firstWrong;
};

// Ray-traces the ball per pixel: where the camera ray hits it, the reflected direction names the wall the
// pixel must show. Pixels whose reflection lands near a wall edge (or near the silhouette) are not checked.
Check checkReflections(const Image& image, const FrameInput& input) {
    const Camera& camera = input.camera;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double t = std::tan(glm::radians(camera.fovY) * 0.5);
    Check check;
    for (int y = 2; y < kHeight; y += 3)
        for (int x = 2; x < kWidth; x += 3) {
            const double nx = ((x + 0.5) / kWidth * 2.0 - 1.0) * t;
            const double ny = (1.0 - (y + 0.5) / kHeight * 2.0) * t;
            const glm::dvec3 d = glm::normalize(forward + right * nx + up * ny);
            const glm::dvec3 o = camera.position;
            const double b = glm::dot(o, d), c = glm::dot(o, o) - kRadius * kRadius;
            const double disc = b * b - c;
            if (disc <= 0.0)
                continue;
            const double hit = -b - std::sqrt(disc);
            const glm::dvec3 n = glm::normalize(o + hit * d);
            if (glm::dot(n, -d) < 0.35) // near the silhouette a pixel spans a wide cone of reflections
                continue;
            const glm::dvec3 r = d - 2.0 * glm::dot(d, n) * n;
            if (!awayFromEdges(r, 0.08))
                continue;
            const glm::dvec3 expected = kWallColors[wallOf(r)];
            const glm::vec4 got = image.at(x, y);
            ++check.checked;
            if (glm::length(glm::dvec3(got) - expected) > 0.1) {
                if (check.wrong++ == 0)
                    check.firstWrong = "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                       ") shows (" + std::to_string(got.r) + ", " + std::to_string(got.g) +
                                       ", " + std::to_string(got.b) + "), expected wall " +
                                       std::to_string(wallOf(r));
            }
        }
    return check;
}

struct Variant {
    ReflectorMap map;
    ReflectorFill fill;
    const char* name;
};

class ReflectorMaps : public GlTest, public ::testing::WithParamInterface<Variant> {};

TEST_P(ReflectorMaps, BallShowsTheWallItsReflectionPointsAt) {
    const FrameInput input = ballInRoom(GetParam().map, GetParam().fill);
    const Image image = renderImage(input, kWidth, kHeight);
    ASSERT_EQ(image.width, kWidth);
    EXPECT_EQ(lastReport().countRan(PassKind::Envmap), 1u);
    const Check check = checkReflections(image, input);
    EXPECT_GT(check.checked, 500);
    // Every wall, the one behind the camera included, is seen somewhere in the ball: all checked.
    EXPECT_EQ(check.wrong, 0) << check.wrong << " of " << check.checked
                              << " wrong; first: " << check.firstWrong;
}

INSTANTIATE_TEST_SUITE_P(
    AllMaps, ReflectorMaps,
    ::testing::Values(Variant{ReflectorMap::Cube, ReflectorFill::Resampled, "cube"},
                      Variant{ReflectorMap::DualParaboloid, ReflectorFill::Direct, "paraboloidDirect"},
                      Variant{ReflectorMap::DualParaboloid, ReflectorFill::Resampled, "paraboloidResampled"},
                      Variant{ReflectorMap::TennisBall, ReflectorFill::Direct, "tennisBallDirect"},
                      Variant{ReflectorMap::TennisBall, ReflectorFill::Resampled, "tennisBallResampled"},
                      Variant{ReflectorMap::Octahedral, ReflectorFill::Resampled, "octahedral"},
                      Variant{ReflectorMap::Octahedral, ReflectorFill::Direct, "octahedralAskedDirect"}),
    [](const auto& info) { return std::string(info.param.name); });

class ReflectorFrames : public GlTest {};

TEST_F(ReflectorFrames, StaticSceneRendersItsEnvironmentOnce) {
    FrameInput input = ballInRoom(ReflectorMap::DualParaboloid, ReflectorFill::Resampled);
    const Image first = renderImage(input, 64, 64);
    auto countEnvmap = [](const FrameReport& report) { return int(report.countRan(PassKind::Envmap)); };
    EXPECT_EQ(countEnvmap(lastReport()), 1);
    // The camera moves, the scene does not: the second frame spends nothing on the environment.
    input.camera.position = {0.5, 0.3, 3.0};
    const Image second = renderImage(input, 64, 64);
    EXPECT_EQ(countEnvmap(lastReport()), 0);
    bool explained = false;
    for (const auto& s : lastReport().skipped)
        explained = explained || (s.target == "Ball" && s.code == PlanReason::EnvmapUnchanged);
    EXPECT_TRUE(explained);
    // ... and still shows the map: the ball's centre pixel reflects a wall, not black.
    const glm::vec4 centre = second.at(32, 32);
    EXPECT_GT(centre.r + centre.g + centre.b, 0.5f);
    // A wall moves: the map is rendered again.
    input.items[0].world[3].x += 1.0;
    renderImage(input, 64, 64);
    EXPECT_EQ(countEnvmap(lastReport()), 1);
}

// The largest difference of any channel between two images of one size.
float largestDifference(const Image& a, const Image& b) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i)
        worst = std::max(worst, std::abs(a.rgba[i] - b.rgba[i]));
    return a.rgba.size() == b.rgba.size() ? worst : 1e9f;
}

TEST_F(ReflectorFrames, TimeSlicedMapRedrawsOneFaceAFrameAndConvergesToTheFullMap) {
    FrameInput input = ballInRoom(ReflectorMap::Cube, ReflectorFill::Resampled);
    input.reflectors[0].update = ReflectorUpdate::TimeSliced;
    renderImage(input, 64, 64);
    ASSERT_EQ(lastReport().countRan(PassKind::Envmap), 1u);
    // Every wall takes its neighbour's colour: every face of the map is out of date.
    for (int wall = 0; wall < 6; ++wall)
        input.items[static_cast<std::size_t>(wall)].material = emissive(kWallColors[(wall + 1) % 6]);
    // What a map drawn whole shows, from a renderer of its own.
    auto created = Renderer::create();
    ASSERT_TRUE(created.ok()) << created.error();
    std::unique_ptr<Renderer> other = std::move(*created);
    auto whole = renderStill(*other, input, StillSettings{64, 64, 1});
    ASSERT_TRUE(whole.ok()) << whole.error();
    other.reset();

    std::vector<int> faces;
    std::vector<float> differences;
    for (int frame = 0; frame < 6; ++frame) {
        const Image image = renderImage(input, 64, 64);
        ASSERT_EQ(lastReport().countRan(PassKind::Envmap), 1u) << "frame " << frame;
        ASSERT_FALSE(lastReport().plan.envmaps.empty());
        for (const EnvmapFace& face : lastReport().plan.envmaps[0].faces)
            faces.push_back(face.index);
        differences.push_back(largestDifference(image, whole->image));
        // The editor draws another frame while faces are out of date.
        EXPECT_EQ(lastReport().mapSettling, frame < 5) << "frame " << frame;
    }
    EXPECT_EQ(faces, (std::vector{0, 1, 2, 3, 4, 5})) << "one face a frame, in turn";
    // Until the last face is drawn the ball still shows some old walls; then exactly the whole map.
    for (int frame = 0; frame < 5; ++frame) {
        EXPECT_GT(differences[static_cast<std::size_t>(frame)], 0.5f) << "frame " << frame;
    }
    EXPECT_LE(differences[5], 1e-6f);
    // Converged: nothing more to draw while nothing changes.
    renderImage(input, 64, 64);
    EXPECT_EQ(lastReport().countRan(PassKind::Envmap), 0u);
}

TEST_F(ReflectorFrames, MirrorsInTheEnvironmentReflectToTheirDepthBudget) {
    // A half-silvered mirror in front of the +X (red) wall, facing the ball: what the ball sees towards +X is
    // half the mirror's (grey, emissive) surface and half its reflection of the room, whose far wall is the
    // −X (green) one. With mirrorDepth 0 the reflection is not followed: the surface's half alone.
    FrameInput input = ballInRoom(ReflectorMap::Cube, ReflectorFill::Resampled);
    Mirror mirror;
    mirror.name = "Mirror";
    mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(10, 0, 0)), glm::radians(90.0),
                               glm::dvec3(0, 0, 1)); // local +Y → −X: facing the ball
    mirror.size = {30.0, 30.0};
    mirror.material = emissive({0.5, 0.5, 0.5});
    mirror.hasMaterial = true;
    mirror.reflectivity = 0.5;
    input.mirrors.push_back(mirror);
    input.camera.position = {3.2, 0.0, 0.0}; // looking from +X at the ball: its centre reflects +X
    input.camera.up = {0.0, 1.0, 0.0};
    auto centre = [&](int depth) {
        input.reflectors[0].mirrorDepth = depth;
        return glm::dvec3(renderImage(input, 64, 64).at(32, 32));
    };
    const glm::dvec3 reflected = centre(1);
    EXPECT_LT(glm::length(reflected - (glm::dvec3(0.25) + 0.5 * kWallColors[1])), 0.1)
        << reflected.x << " " << reflected.y << " " << reflected.z;
    const glm::dvec3 surfaceAlone = centre(0);
    EXPECT_LT(glm::length(surfaceAlone - glm::dvec3(0.25)), 0.05)
        << surfaceAlone.x << " " << surfaceAlone.y << " " << surfaceAlone.z;
}

// A mirror's Fresnel is drawn into the map (its surface in pass 1), so with update on-change toggling it
// draws the map again instead of keeping the old reflection; an unchanged frame reuses it.
TEST_F(ReflectorFrames, TogglingAMirrorsFresnelRedrawsAnOnChangeMap) {
    FrameInput input = ballInRoom(ReflectorMap::Cube, ReflectorFill::Resampled);
    input.reflectors[0].update = ReflectorUpdate::OnChange;
    Mirror mirror;
    mirror.name = "Mirror";
    mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(10, 0, 0)), glm::radians(90.0),
                               glm::dvec3(0, 0, 1));
    mirror.size = {30.0, 30.0};
    mirror.reflectivity = 0.3;
    input.mirrors.push_back(mirror);
    // Why the envmap pass ran; none when it did not.
    auto envmapCode = [](const FrameReport& report) -> std::optional<PlanReason> {
        for (const PassRun& run : report.ran)
            if (report.planned(run).kind == PassKind::Envmap)
                return report.planned(run).code;
        return std::nullopt;
    };
    renderImage(input, 64, 64);
    ASSERT_TRUE(envmapCode(lastReport())) << "the first frame draws the map";
    renderImage(input, 64, 64);
    EXPECT_FALSE(envmapCode(lastReport())) << "nothing changed: the map is reused";
    input.mirrors[0].fresnel = true;
    renderImage(input, 64, 64);
    EXPECT_EQ(envmapCode(lastReport()), PlanReason::EnvmapChanged);
    renderImage(input, 64, 64);
    EXPECT_FALSE(envmapCode(lastReport())) << "redrawn once, then reused again";
}

// Two mirrors in the ball's environment, for every map and fill. The camera looks at the ball from −Z, so
// the ball's centre reflects −Z, where mirror A faces it. A reflects the ball's surroundings towards +Z,
// where mirror B stands behind the ball, turned 45° so that it reflects +X, where a white box stands (large:
// it is 35 units away in the reflections). Both are half-silvered, so each level adds half of what the
// last showed: the centre shows half of A's own grey at mirror depth 0 (its reflection not followed), and
// half of B's orange beneath at depth 1, and half of the white box beneath B's at depth 2; depth 3 adds
// nothing more (the box is no mirror).
class ReflectorMirrorDepth : public GlTest, public ::testing::WithParamInterface<Variant> {};

glm::dmat4 mirrorFacing(const glm::dvec3& at, const glm::dvec3& normal) {
    // Local +Y (the reflective side) onto `normal`; any right-handed frame around it.
    const glm::dvec3 y = glm::normalize(normal);
    const glm::dvec3 x =
        glm::normalize(glm::cross(std::abs(y.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0), y));
    const glm::dvec3 z = glm::cross(x, y);
    return glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0), glm::dvec4(z, 0.0), glm::dvec4(at, 1.0));
}

TEST_P(ReflectorMirrorDepth, MirrorsInTheMapReflectToTheReflectorsBudget) {
    FrameInput input = ballInRoom(GetParam().map, GetParam().fill);
    Mirror a;
    a.name = "A";
    a.world = mirrorFacing({0.0, 0.0, -10.0}, {0.0, 0.0, 1.0});
    a.size = {12.0, 12.0};
    a.material = emissive({0.5, 0.5, 0.5});
    a.hasMaterial = true;
    a.reflectivity = 0.5;
    Mirror b = a;
    b.name = "B";
    b.world = mirrorFacing({0.0, 0.0, 8.0}, {1.0, 0.0, -1.0});
    b.size = {8.0, 8.0};
    b.material = emissive({1.0, 0.5, 0.0});
    input.mirrors = {a, b};
    static const auto box = std::make_shared<const MeshData>(makeBox());
    input.items.push_back(
        {"White box",
         glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(8.0, 0.0, 8.0)), glm::dvec3(1.0, 5.0, 5.0)),
         box, emissive({1.0, 1.0, 1.0}), false});
    input.camera.position = {0.0, 0.0, -3.2};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.up = {0.0, 1.0, 0.0};
    auto centre = [&](int depth) {
        input.reflectors[0].mirrorDepth = depth;
        const glm::dvec3 c(renderImage(input, 64, 64).at(32, 32));
        EXPECT_EQ(lastReport().countRan(PassKind::Envmap), 1u)
            << "depth " << depth << ": a new mirror depth must render the map again";
        return c;
    };
    // A's surface: 0.5·grey; B's surface seen in A: 0.5·0.5·orange; the box seen in B seen in A: 0.25·white.
    const glm::dvec3 expected[] = {
        {0.25, 0.25, 0.25}, {0.5, 0.375, 0.25}, {0.75, 0.625, 0.5}, {0.75, 0.625, 0.5}};
    for (int depth = 0; depth < 4; ++depth) {
        const glm::dvec3 got = centre(depth);
        EXPECT_LT(glm::length(got - expected[depth]), 0.1) << GetParam().name << " depth " << depth << ": ("
                                                           << got.x << ", " << got.y << ", " << got.z << ")";
    }
}

INSTANTIATE_TEST_SUITE_P(
    AllMaps, ReflectorMirrorDepth,
    ::testing::Values(Variant{ReflectorMap::Cube, ReflectorFill::Resampled, "cube"},
                      Variant{ReflectorMap::DualParaboloid, ReflectorFill::Direct, "paraboloidDirect"},
                      Variant{ReflectorMap::DualParaboloid, ReflectorFill::Resampled, "paraboloidResampled"},
                      Variant{ReflectorMap::TennisBall, ReflectorFill::Direct, "tennisBallDirect"},
                      Variant{ReflectorMap::TennisBall, ReflectorFill::Resampled, "tennisBallResampled"},
                      Variant{ReflectorMap::Octahedral, ReflectorFill::Resampled, "octahedral"},
                      Variant{ReflectorMap::Octahedral, ReflectorFill::Direct, "octahedralAskedDirect"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(ReflectorFrames, ClosedMeshAroundTheCapturePointKeepsItsInsideFaces) {
    // The environment pass culls the back faces of closed meshes it sees from outside. A room made of one
    // closed box around the ball is seen from inside, by its back faces: it must still fill the map.
    FrameInput input = ballInRoom(ReflectorMap::DualParaboloid, ReflectorFill::Direct);
    static const auto box = std::make_shared<const MeshData>(makeBox());
    input.items = {
        {"Room", glm::scale(glm::dmat4(1.0), glm::dvec3(10.0)), box, emissive({0.2, 0.6, 0.3}), false}};
    for (ReflectorMap map : {ReflectorMap::Cube, ReflectorMap::DualParaboloid}) {
        input.reflectors[0].map = map;
        const glm::dvec3 centre(renderImage(input, 64, 64).at(32, 32));
        EXPECT_LT(glm::length(centre - glm::dvec3(0.2, 0.6, 0.3)), 0.05)
            << centre.x << " " << centre.y << " " << centre.z;
    }
}

TEST_F(ReflectorFrames, ParallaxCorrectionMovesNearbyReflectionsWhereTheyBelong) {
    // The ball sits off-centre in a small room (half 3): without correction the walls appear as if seen
    // from the ball's centre; with a box proxy of the room, the reflection at each pixel matches the wall
    // a ray from the surface point really meets.
    FrameInput input = ballInRoom(ReflectorMap::Cube, ReflectorFill::Resampled);
    constexpr double kHalf = 3.0;
    constexpr int kSize = 128;
    for (DrawItem& wall : input.items) {
        const glm::dvec3 centre = glm::dvec3(wall.world[3]) * (kHalf / kRoomHalf);
        wall.world = glm::translate(glm::dmat4(1.0), centre) *
                     glm::scale(glm::dmat4(glm::dmat3(wall.world)), glm::dvec3(kHalf / kRoomHalf));
        wall.world[3] = glm::dvec4(centre, 1.0);
    }
    input.camera.position = {0.0, 0.0, 2.9};
    input.camera.fovY = 32.0;
    input.reflectors[0].world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.8, 0.6, 0.0)) *
                                glm::scale(glm::dmat4(1.0), glm::dvec3(0.7));
    input.camera.target = {0.8, 0.6, 0.0};
    auto score = [&](const Image& image) {
        // Fraction of ball pixels showing the wall that the exact reflected ray from the surface meets.
        const Camera& camera = input.camera;
        const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
        const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
        const glm::dvec3 up = glm::cross(right, forward);
        const double t = std::tan(glm::radians(camera.fovY) * 0.5);
        const glm::dvec3 c(0.8, 0.6, 0.0);
        int total = 0, right_ = 0;
        for (int y = 1; y < kSize; y += 2)
            for (int x = 1; x < kSize; x += 2) {
                const double nx = ((x + 0.5) / kSize * 2.0 - 1.0) * t,
                             ny = (1.0 - (y + 0.5) / kSize * 2.0) * t;
                const glm::dvec3 d = glm::normalize(forward + right * nx + up * ny);
                const glm::dvec3 o = camera.position - c;
                const double b = glm::dot(o, d), cc = glm::dot(o, o) - 0.49;
                if (b * b - cc <= 0.0)
                    continue;
                const glm::dvec3 p = o - (b + std::sqrt(b * b - cc)) * d;
                const glm::dvec3 n = glm::normalize(p);
                if (glm::dot(n, -d) < 0.4)
                    continue;
                const glm::dvec3 r = d - 2.0 * glm::dot(d, n) * n;
                // Exact: the wall the ray p + s·r leaves the room [−3, 3]³ through (world = p + c).
                const glm::dvec3 q = p + c;
                double best = 1e30;
                int wall = 0;
                for (int a = 0; a < 3; ++a) {
                    if (r[a] == 0.0)
                        continue;
                    const double s = ((r[a] > 0 ? kHalf : -kHalf) - q[a]) / r[a];
                    if (s < best) {
                        best = s;
                        wall = 2 * a + (r[a] > 0 ? 0 : 1);
                    }
                }
                ++total;
                if (glm::length(glm::dvec3(image.at(x, y)) - kWallColors[wall]) < 0.3)
                    ++right_;
            }
        return total > 0 ? double(right_) / total : 0.0;
    };
    const Image plainImage = renderImage(input, kSize, kSize);
    const double plain = score(plainImage);
    input.reflectors[0].parallax = ParallaxParams{.shape = ParallaxShape::Box};
    input.reflectors[0].parallax->min = glm::dvec3(-kHalf) - glm::dvec3(0.8, 0.6, 0.0);
    input.reflectors[0].parallax->max = glm::dvec3(kHalf) - glm::dvec3(0.8, 0.6, 0.0);
    const Image correctedImage = renderImage(input, kSize, kSize);
    const double corrected = score(correctedImage);
    // The misses left are pixels on a boundary between two walls, whose filtered colour is a blend.
    EXPECT_GT(corrected, 0.95) << "plain " << plain << ", corrected " << corrected;
    EXPECT_GT(corrected, plain + 0.04) << "plain " << plain << ", corrected " << corrected;
    std::printf("parallax: %.1f%% of ball pixels right without correction, %.1f%% with a box proxy\n",
                100.0 * plain, 100.0 * corrected);
}

} // namespace
} // namespace speculum::test
