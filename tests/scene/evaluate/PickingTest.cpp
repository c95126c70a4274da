// Click-to-select on the CPU: the nearest surface wins, clicking a reflection selects the reflected object,
// mirrors seen from behind or at the depth limit select the mirror, and the editor's pick scene follows the
// document (node ids, parents' transforms, animations).
#include "scene/evaluate/Picking.hpp"

#include "editor/document/Commands.hpp"
#include "editor/document/NodeFactory.hpp"
#include "render/mesh/Primitives.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QUndoStack>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <random>

namespace {

using namespace speculum;
using namespace speculum::document;
using namespace speculum::scene;

render::MeshHandle sphere() {
    static const render::MeshHandle mesh = std::make_shared<render::MeshData>(render::makeSphere(24));
    return mesh;
}

glm::dmat4 at(const glm::dvec3& p, double scale = 1.0) {
    return glm::scale(glm::translate(glm::dmat4(1.0), p), glm::dvec3(scale));
}

// Every triangle tried, as picking did before it had a hierarchy: the reference the hierarchy must match.
std::optional<double> bruteForce(const render::MeshData& m, const glm::dvec3& o, const glm::dvec3& d) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const glm::dvec3 a(m.positions[m.indices[i]]), b(m.positions[m.indices[i + 1]]),
            c(m.positions[m.indices[i + 2]]);
        const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-300) {
            continue;
        }
        const glm::dvec3 s = o - a, q = glm::cross(s, e1);
        const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
        if (u >= 0 && v >= 0 && u + v <= 1 && t > 1e-9 && t < best) {
            best = t;
        }
    }
    return std::isfinite(best) ? std::optional<double>(best) : std::nullopt;
}

// A height field of `cells`² quads (2·cells² triangles) over [-1, 1]² in XZ with gentle waves.
render::MeshHandle terrain(int cells) {
    auto mesh = std::make_shared<render::MeshData>();
    const int n = cells + 1;
    mesh->positions.reserve(std::size_t(n) * n);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const float x = -1.0f + 2.0f * float(i) / float(cells),
                        z = -1.0f + 2.0f * float(j) / float(cells);
            mesh->positions.emplace_back(x, 0.1f * std::sin(7.0f * x) * std::cos(5.0f * z), z);
        }
    }
    mesh->indices.reserve(std::size_t(cells) * cells * 6);
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            const std::uint32_t a = std::uint32_t(j * n + i), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
            mesh->indices.insert(mesh->indices.end(), {a, c, b, b, c, d});
        }
    }
    return mesh;
}

TEST(Picking, HierarchyFindsTheSameNearestHitAsEveryTriangle) {
    // A triangle soup of very different sizes (large and tiny, overlapping), plus a sphere: the hierarchy's
    // nearest hit is the brute-force one for every ray, hits and misses alike.
    auto soup = std::make_shared<render::MeshData>(render::makeSphere(12));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 c(unit(rng) * 2.0f, unit(rng) * 2.0f, unit(rng) * 2.0f);
        const float size = i % 10 == 0 ? 1.5f : 0.02f;
        const auto base = std::uint32_t(soup->positions.size());
        for (int k = 0; k < 3; ++k) {
            soup->positions.push_back(c + size * glm::vec3(unit(rng), unit(rng), unit(rng)));
        }
        soup->indices.insert(soup->indices.end(), {base, base + 1, base + 2});
    }
    const speculum::scene::MeshPickAccel accel(*soup);
    EXPECT_EQ(accel.triangleCount(), soup->triangleCount());
    int hits = 0;
    for (int r = 0; r < 2000; ++r) {
        const glm::dvec3 o(unit(rng) * 5.0, unit(rng) * 5.0, unit(rng) * 5.0);
        // Mostly towards the soup, so many rays hit (and pass through several leaves).
        glm::dvec3 d = glm::dvec3(unit(rng), unit(rng), unit(rng)) * 2.0 - o;
        if (r % 7 == 0) {
            d = glm::dvec3(0.0, 0.0, r % 2 ? 1.0 : -1.0); // axis-parallel rays take the 1/0 path
        }
        const auto expected = bruteForce(*soup, o, d);
        const auto got = accel.intersect(*soup, o, d);
        ASSERT_EQ(expected.has_value(), got.has_value()) << "ray " << r;
        if (expected) {
            ++hits;
            EXPECT_NEAR(*got, *expected, 1e-9 * std::max(1.0, *expected)) << "ray " << r;
        }
    }
    EXPECT_GT(hits, 600) << "the rays should test something";
}

TEST(Picking, BigMeshBuildsItsHierarchyOnceAndReusesIt) {
    const render::MeshHandle big = terrain(1000); // 2 000 000 triangles
    ASSERT_EQ(big->triangleCount(), 2000000u);
    speculum::scene::PickScene scene;
    scene.meshes.push_back({42, big, at({0, 0, -3}, 2.0)});
    const speculum::scene::PickCacheStats before = speculum::scene::pickCacheStats();
    // The first click answers at once (scanning, while the hierarchy builds in the background) ...
    const auto first = speculum::scene::pick(scene, speculum::scene::Ray{{0.3, 5, -3.2}, {0, -1, 0}});
    ASSERT_TRUE(first);
    EXPECT_EQ(first->id, 42u);
    const double expectedY = 2.0 * 0.1 * std::sin(7.0 * 0.15) * std::cos(5.0 * -0.1);
    EXPECT_NEAR(first->point.y, expectedY, 1e-4);
    // ... and there is exactly one build of it, whoever asks while it runs.
    const auto accel = speculum::scene::meshPickAccel(big);
    EXPECT_EQ(speculum::scene::meshPickAccel(big), accel);
    const speculum::scene::PickCacheStats afterFirst = speculum::scene::pickCacheStats();
    EXPECT_EQ(afterFirst.accelBuilds, before.accelBuilds + 1) << "one build for the mesh";
    const auto again = speculum::scene::pick(scene, speculum::scene::Ray{{0.3, 5, -3.2}, {0, -1, 0}});
    ASSERT_TRUE(again);
    EXPECT_NEAR(again->point.y, first->point.y, 1e-9) << "the hierarchy finds the same point as the scan";

    // Later clicks (other rays too) reuse it, and so does a second node drawing the same mesh.
    scene.meshes.push_back({43, big, at({10, 0, -3}, 2.0)});
    for (int i = 0; i < 20; ++i) {
        const auto hit =
            speculum::scene::pick(scene, speculum::scene::Ray{{-1.5 + 0.15 * i, 5, -3.5}, {0, -1, 0}});
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->id, 42u);
    }
    EXPECT_EQ(speculum::scene::pick(scene, speculum::scene::Ray{{10, 5, -3}, {0, -1, 0}})->id, 43u);
    EXPECT_EQ(speculum::scene::pickCacheStats().accelBuilds, afterFirst.accelBuilds)
        << "no rebuild per click";
    const render::Bounds b = speculum::scene::meshBounds(big);
    EXPECT_EQ(speculum::scene::pickCacheStats().boundsBuilds, afterFirst.boundsBuilds)
        << "bounds came with the hierarchy";
    EXPECT_FLOAT_EQ(b.min.x, -1.0f);
    EXPECT_FLOAT_EQ(b.max.z, 1.0f);

    // A new mesh (even at a reused address once the old one is gone) gets its own.
    const std::size_t entries = speculum::scene::pickCacheStats().entries;
    const render::MeshHandle small = terrain(4);
    EXPECT_EQ(speculum::scene::meshPickAccel(small)->triangleCount(), 32u);
    EXPECT_EQ(speculum::scene::pickCacheStats().accelBuilds, afterFirst.accelBuilds + 1);
    EXPECT_EQ(speculum::scene::pickCacheStats().entries, entries + 1);
}

TEST(Picking, NearestSurfaceWinsAndMissesAreEmpty) {
    speculum::scene::PickScene scene;
    scene.meshes.push_back({1, sphere(), at({0, 0, -5})});
    scene.meshes.push_back({2, sphere(), at({0, 0, -10}, 3.0)});
    const auto hit = speculum::scene::pick(scene, speculum::scene::Ray{{0, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, 1u);
    EXPECT_NEAR(hit->distance, 4.0, 0.01);
    EXPECT_EQ(hit->reflections, 0);

    const auto side = speculum::scene::pick(
        scene, speculum::scene::Ray{{2.0, 0, 0}, {0, 0, -1}}); // past the small sphere, into the big one
    ASSERT_TRUE(side);
    EXPECT_EQ(side->id, 2u);
    EXPECT_FALSE(speculum::scene::pick(scene, speculum::scene::Ray{{0, 0, 0}, {0, 0, 1}}))
        << "nothing behind the camera";
    EXPECT_FALSE(speculum::scene::pick(scene, speculum::scene::Ray{{0, 0, 0}, {0, 1, 0}}));
}

TEST(Picking, ClickingAReflectionSelectsTheReflectedObject) {
    // A floor mirror at y = -1 facing up; a sphere above it and in front of the camera, out of direct view.
    speculum::scene::PickScene scene;
    scene.mirrors.push_back({10, at({0, -1, -5}), {10.0, 10.0}});
    scene.meshes.push_back({1, sphere(), at({0, 1, -8}, 0.5)});
    // Aim at the floor where the sphere's reflection is: the sphere's mirror image sits at y = -3.
    const glm::dvec3 image(0, -3, -8);
    const speculum::scene::Ray ray{{0, 0, 0}, image};
    const auto direct = speculum::scene::pick(speculum::scene::PickScene{scene.meshes, {}, 3}, ray);
    EXPECT_FALSE(direct) << "without the mirror the ray goes below the sphere";
    const auto hit = speculum::scene::pick(scene, ray);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, 1u) << "the reflected sphere, not the mirror";
    EXPECT_EQ(hit->reflections, 1);
    EXPECT_EQ(hit->firstMirror, 10u);
    EXPECT_NEAR(glm::length(hit->point - glm::dvec3(0, 1, -8)), 0.5, 0.01) << "a point on the sphere";
    EXPECT_LT(hit->point.y, 1.0) << "on its underside, the side the mirror sees";

    // Where the reflection shows nothing, the click selects the mirror itself.
    const auto empty = speculum::scene::pick(scene, speculum::scene::Ray{{0, 0, 0}, {3, -1, -5}});
    ASSERT_TRUE(empty);
    EXPECT_EQ(empty->id, 10u);

    // With no reflections allowed, the mirror.
    scene.mirrorDepth = 0;
    const auto flat = speculum::scene::pick(scene, ray);
    ASSERT_TRUE(flat);
    EXPECT_EQ(flat->id, 10u);
}

TEST(Picking, MirrorSeenFromBehindIsOpaque) {
    speculum::scene::PickScene scene;
    // The reflective side (+Y) turned to -Z: away from a camera at the origin looking down -Z.
    const glm::dmat4 facingAway = glm::rotate(at({0, 0, -5}), glm::radians(-90.0), glm::dvec3(1, 0, 0));
    scene.mirrors.push_back({10, facingAway, {4.0, 4.0}});
    scene.meshes.push_back({1, sphere(), at({0, 0, 3})}); // behind the camera: only a reflection shows it
    const auto hit = speculum::scene::pick(scene, speculum::scene::Ray{{0, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, 10u);
    EXPECT_EQ(hit->reflections, 0);
    // Turned towards the camera, the same ray is reflected back to the sphere behind the camera.
    scene.mirrors.front().world = glm::rotate(at({0, 0, -5}), glm::radians(90.0), glm::dvec3(1, 0, 0));
    const auto back = speculum::scene::pick(scene, speculum::scene::Ray{{0, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(back);
    EXPECT_EQ(back->id, 1u);
}

TEST(Picking, TwoFacingMirrorsStopAtTheDepthLimit) {
    speculum::scene::PickScene scene;
    // Two parallel mirrors facing each other along X; a ray bouncing between them forever.
    scene.mirrors.push_back(
        {10, glm::rotate(at({-2, 0, 0}), glm::radians(-90.0), glm::dvec3(0, 0, 1)), {4, 4}});
    scene.mirrors.push_back(
        {11, glm::rotate(at({2, 0, 0}), glm::radians(90.0), glm::dvec3(0, 0, 1)), {4, 4}});
    scene.mirrorDepth = 3;
    const auto hit = speculum::scene::pick(scene, speculum::scene::Ray{{0, 0, 0}, {1, 0, 0.01}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->reflections, 3);
    EXPECT_TRUE(hit->id == 10u || hit->id == 11u);
}

TEST(Picking, CameraRayGoesThroughTheImageCorners) {
    render::Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, -1};
    camera.fovY = 90.0;
    const speculum::scene::Ray centre = speculum::scene::cameraRay(camera, 2.0, 0.0, 0.0);
    EXPECT_NEAR(glm::length(glm::normalize(centre.direction) - glm::dvec3(0, 0, -1)), 0.0, 1e-12);
    const speculum::scene::Ray top = speculum::scene::cameraRay(camera, 2.0, 0.0, 1.0);
    EXPECT_NEAR(glm::degrees(std::atan2(top.direction.y, -top.direction.z)), 45.0, 1e-9);
    const speculum::scene::Ray right = speculum::scene::cameraRay(camera, 2.0, 1.0, 0.0);
    EXPECT_NEAR(right.direction.x / -right.direction.z, 2.0, 1e-9);
}

TEST(PickScene, FollowsTheDocument) {
    speculum::scene::Scene scene;
    QUndoStack stack;
    speculum::scene::NodeTree parent = makeNode(NewNodeKind::Empty, {0, 0, -5});
    speculum::scene::NodeTree child = makeNode(NewNodeKind::Sphere, {1, 0, 0});
    child.data.transform.scale = glm::dvec3(0.5);
    parent.children.push_back(child);
    auto* add = new AddNodeCommand(scene, parent);
    stack.push(add);
    auto* mirror = new AddNodeCommand(scene, makeNode(NewNodeKind::Mirror, {0, -2, -5}));
    stack.push(mirror);
    const speculum::scene::NodeId sphereId = scene.findNode(add->nodeId())->child(0)->id();

    speculum::scene::MeshLibrary meshes;
    const speculum::scene::PickScene picks = speculum::scene::buildPickScene(scene, 0.0, meshes);
    ASSERT_EQ(picks.meshes.size(), 1u);
    ASSERT_EQ(picks.mirrors.size(), 1u);
    EXPECT_EQ(picks.meshes.front().id, sphereId);
    EXPECT_EQ(picks.mirrors.front().id, mirror->nodeId());
    // The sphere's world centre is parent translate + child translate.
    const auto hit = speculum::scene::pick(picks, speculum::scene::Ray{{1, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, sphereId);
    EXPECT_NEAR(hit->point.z, -4.5, 0.01);
    EXPECT_EQ(glm::dvec3(speculum::scene::parentWorldMatrix(scene, sphereId, 0.0)[3]), glm::dvec3(0, 0, -5));
}

} // namespace
