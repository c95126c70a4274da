#include "editor/document/Picking.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

namespace speculum::document {

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// Slab test against the mesh's local box: most meshes are missed here without touching a triangle.
bool hitsBox(const glm::dvec3& origin, const glm::dvec3& dir, const render::Bounds& b) {
    double t0 = 0.0, t1 = kNone;
    for (int i = 0; i < 3; ++i) {
        const double lo = double(b.min[i]) - 1e-6, hi = double(b.max[i]) + 1e-6;
        if (std::abs(dir[i]) < 1e-300) {
            if (origin[i] < lo || origin[i] > hi) {
                return false;
            }
            continue;
        }
        double a = (lo - origin[i]) / dir[i], c = (hi - origin[i]) / dir[i];
        if (a > c) {
            std::swap(a, c);
        }
        t0 = std::max(t0, a);
        t1 = std::min(t1, c);
        if (t0 > t1) {
            return false;
        }
    }
    return true;
}

// Möller–Trumbore, both sides (a click on the inside of an open mesh still selects it).
double intersectTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                         const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) {
        return kNone;
    }
    const double inv = 1.0 / det;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) {
        return kNone;
    }
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) * inv;
    if (v < 0.0 || u + v > 1.0) {
        return kNone;
    }
    return glm::dot(e2, q) * inv;
}

struct MirrorHit {
    double t = kNone;
    bool front = false;
};

MirrorHit intersectMirror(const PickMirror& mirror, const Ray& ray) {
    const glm::dmat4 inv = glm::inverse(mirror.world);
    const glm::dvec3 o = glm::dvec3(inv * glm::dvec4(ray.origin, 1.0));
    const glm::dvec3 d = glm::dvec3(inv * glm::dvec4(ray.direction, 0.0));
    if (std::abs(d.y) < 1e-300) {
        return {};
    }
    const double t = -o.y / d.y;
    if (!(t > 0.0)) {
        return {};
    }
    const glm::dvec3 p = o + d * t;
    if (std::abs(p.x) > mirror.size.x * 0.5 || std::abs(p.z) > mirror.size.y * 0.5) {
        return {};
    }
    return {t, o.y > 0.0};
}

} // namespace

std::optional<double> intersectMesh(const PickMesh& mesh, const Ray& ray) {
    if (!mesh.mesh || mesh.mesh->indices.empty()) {
        return std::nullopt;
    }
    // In the mesh's local space with an unnormalised direction, t is the same parameter as in world space.
    const glm::dmat4 inv = glm::inverse(mesh.world);
    const glm::dvec3 o = glm::dvec3(inv * glm::dvec4(ray.origin, 1.0));
    const glm::dvec3 d = glm::dvec3(inv * glm::dvec4(ray.direction, 0.0));
    const render::MeshData& m = *mesh.mesh;
    if (!hitsBox(o, d, render::computeBounds(m))) {
        return std::nullopt;
    }
    double best = kNone;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const double t = intersectTriangle(o, d, glm::dvec3(m.positions[m.indices[i]]),
                                           glm::dvec3(m.positions[m.indices[i + 1]]),
                                           glm::dvec3(m.positions[m.indices[i + 2]]));
        if (t > 1e-9 && t < best) {
            best = t;
        }
    }
    if (best == kNone) {
        return std::nullopt;
    }
    return best;
}

std::optional<PickHit> pick(const PickScene& scene, const Ray& start) {
    Ray ray = start;
    double travelled = 0.0;
    std::uint64_t firstMirror = 0;
    std::uint64_t lastMirror = 0;
    bool bounced = false;
    std::optional<PickHit>
        mirrorItself; // what a click on the first mirror selects if the reflection is empty
    for (int reflections = 0;; ++reflections) {
        const double length = glm::length(ray.direction);
        if (!(length > 0.0) || !std::isfinite(length)) {
            return mirrorItself;
        }
        double best = kNone;
        std::uint64_t bestId = 0;
        for (const PickMesh& m : scene.meshes) {
            if (auto t = intersectMesh(m, ray); t && *t < best) {
                best = *t;
                bestId = m.id;
            }
        }
        const PickMirror* mirror = nullptr;
        MirrorHit mirrorHit;
        for (const PickMirror& m : scene.mirrors) {
            // The mirror just left cannot be hit again at t ≈ 0 (a ray from a plane leaves it).
            if (bounced && m.id == lastMirror) {
                continue;
            }
            const MirrorHit h = intersectMirror(m, ray);
            if (h.t < best && h.t < mirrorHit.t) {
                mirrorHit = h;
                mirror = &m;
            }
        }
        if (mirror) {
            best = mirrorHit.t;
        }
        if (best == kNone) {
            return mirrorItself;
        }
        const glm::dvec3 point = ray.origin + ray.direction * best;
        const double distance = travelled + best * length;
        if (!mirror) {
            return PickHit{bestId, point, distance, reflections, firstMirror};
        }
        PickHit onMirror{mirror->id, point, distance, reflections, firstMirror};
        if (!mirrorHit.front || reflections >= scene.mirrorDepth) {
            return onMirror; // a mirror seen in a mirror is a real object too
        }
        if (reflections == 0) {
            firstMirror = mirror->id;
            mirrorItself = onMirror;
        }
        // Reflect about the mirror's world plane (normal = inverse-transpose of the local +Y).
        const glm::dvec3 n = glm::normalize(
            glm::dvec3(glm::inverseTranspose(glm::dmat3(mirror->world)) * glm::dvec3(0.0, 1.0, 0.0)));
        ray.direction = glm::reflect(ray.direction, n);
        ray.origin = point;
        travelled = distance;
        lastMirror = mirror->id;
        bounced = true;
    }
}

Ray cameraRay(const render::Camera& camera, double aspect, double ndcX, double ndcY) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double h = std::tan(glm::radians(camera.fovY) * 0.5);
    return Ray{camera.position, forward + right * (ndcX * h * aspect) + up * (ndcY * h)};
}

} // namespace speculum::document
