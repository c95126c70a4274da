#pragma once

#include "render/FrameInput.hpp"
#include "render/mesh/MeshData.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace speculum::document {

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
std::optional<double> intersectMesh(const PickMesh& mesh, const Ray& ray);

} // namespace speculum::document
