#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/mesh/MeshData.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace speculum::scene {

// Click-to-select on the CPU: a ray against the triangles of the scene's meshes and against its planar
// mirrors. A ray that first meets the reflective (+Y) side of a mirror is reflected and goes on, up to
// `mirrorDepth` times, so clicking an object's reflection selects the object itself. No Qt, no GL.

struct PickMesh {
    std::uint64_t id = 0; // what a hit reports (the editor uses the node id)
    render::MeshHandle mesh;
    glm::dmat4 world{1.0};
};

// The local XZ rectangle of `size` centred at the origin, reflective side towards local +Y.
struct PickMirror {
    std::uint64_t id = 0;
    glm::dmat4 world{1.0};
    glm::dvec2 size{1.0, 1.0};
};

struct PickScene {
    std::vector<PickMesh> meshes;
    std::vector<PickMirror> mirrors;
    int mirrorDepth = 3;
};

struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0}; // need not be unit length
};

struct PickHit {
    std::uint64_t id = 0;
    glm::dvec3 point{0.0};         // world position of the hit (on the last ray)
    double distance = 0.0;         // along all ray segments together, in world units
    int reflections = 0;           // mirrors the ray bounced off before the hit
    std::uint64_t firstMirror = 0; // the mirror clicked, when reflections > 0
};

// The nearest hit, or nothing. A mirror seen from behind or at the depth limit is a hit on that mirror; a
// reflected ray that meets nothing is a hit on the first mirror (the one clicked).
std::optional<PickHit> pick(const PickScene& scene, const Ray& ray);

// The ray through a point of the image: ndc x and y in -1..1 (y up), for the camera's perspective at the
// given aspect ratio (width / height).
Ray cameraRay(const render::Camera& camera, double aspect, double ndcX, double ndcY);

// The nearest intersection of a ray with one mesh in world space (parameter t along ray.direction), if any.
// Goes through the mesh's cached bounding volume hierarchy (meshPickAccel), so a click on a
// multi-million-triangle mesh visits a few dozen triangles, not all of them.
std::optional<double> intersectMesh(const PickMesh& mesh, const Ray& ray);

// A bounding volume hierarchy over one mesh's triangles in the mesh's own coordinates (binned SAH, a few
// triangles per leaf). It keeps no pointer to the mesh: intersect() is given the mesh it was built for.
class MeshPickAccel {
public:
    explicit MeshPickAccel(const render::MeshData& mesh);

    // The nearest t > tMin along origin + t·direction (local coordinates, direction not necessarily unit)
    // over both faces of every triangle, or nothing.
    std::optional<double> intersect(const render::MeshData& mesh, const glm::dvec3& origin,
                                    const glm::dvec3& direction, double tMin = 1e-9) const;

    const render::Bounds& bounds() const { return m_bounds; }
    std::size_t nodeCount() const { return m_nodes.size(); }
    std::size_t triangleCount() const { return m_triangles.size(); }

private:
    struct BvhNode {
        glm::vec3 min, max;
        std::uint32_t first = 0; // leaf: first index into m_triangles; inner: index of the left child
        std::uint32_t count = 0; // leaf: triangles; 0 for an inner node (right child = first + 1)
    };
    std::vector<BvhNode> m_nodes;
    std::vector<std::uint32_t> m_triangles; // triangle numbers in leaf order
    render::Bounds m_bounds;
};

// Per-mesh pick data, cached by mesh identity (the MeshHandle's pointer, as the GPU caches key it) for as
// long as the mesh lives, and shared by every node that draws it. Thread-safe: the editor's import worker
// builds the structures of a new model before the first click needs them.
std::shared_ptr<const MeshPickAccel> meshPickAccel(const render::MeshHandle& mesh);
// The mesh's local bounds, computed once per mesh (every overlay repaint and placement asks).
render::Bounds meshBounds(const render::MeshHandle& mesh);

struct PickCacheStats {
    std::size_t accelBuilds = 0;  // hierarchies built since the process started
    std::size_t boundsBuilds = 0; // bounds computed since the process started
    std::size_t entries = 0;      // meshes cached now
};
PickCacheStats pickCacheStats();

} // namespace speculum::scene
