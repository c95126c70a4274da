#include "render/reference/Shading.hpp"

#include "render/math/ShadowFrustum.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

namespace speculum::render::reference {

namespace {

// GLSL smoothstep; equal edges (a cone without blend) become a step instead of a division by zero.
double smoothstep(double edge0, double edge1, double x) {
    if (!(edge1 > edge0))
        return x >= edge0 ? 1.0 : 0.0;
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Two unit vectors across `dir`, built as lighting.glsl builds its cube-map tap offsets.
void across(const glm::dvec3& dir, glm::dvec3& u, glm::dvec3& v) {
    const double length = glm::length(dir);
    const glm::dvec3 axis = std::abs(dir.y) < 0.99 * length ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    u = glm::normalize(glm::cross(dir, axis));
    v = glm::cross(dir / length, u);
}

} // namespace

std::vector<ShadingLight> shadingLights(const FrameInput& input, const glm::dvec3& origin) {
    // The planner decides which lights get a shadow map (at most kMaxShadowedLights, only with casters
    // and receivers); the reference casts shadow rays for exactly those.
    const FramePlan plan = planFrame(input, PlannerState{});
    std::vector<ShadingLight> lights;
    const std::size_t count = std::min<std::size_t>(input.lights.size(), kMaxLights);
    for (std::size_t i = 0; i < count; ++i) {
        const Light& light = input.lights[i];
        ShadingLight s;
        s.type = light.type;
        s.position = light.position - origin;
        const double length = glm::length(light.direction);
        s.direction = length > 0.0 && std::isfinite(length) ? light.direction / length : glm::dvec3(0, -1, 0);
        s.radiance = light.color * light.intensity;
        const double outer = glm::radians(std::clamp(light.spotAngle, 0.1, 179.0));
        const double inner = outer * (1.0 - std::clamp(light.spotBlend, 0.0, 1.0));
        s.cosOuter = std::cos(outer);
        s.cosInner = std::cos(inner);
        s.shadowed = std::find(plan.shadowedLights.begin(), plan.shadowedLights.end(), static_cast<int>(i)) !=
                     plan.shadowedLights.end();
        if (s.shadowed) {
            s.mapSize = std::max(light.shadows->mapSize, 1);
            s.pcf = std::max(light.shadows->pcf, 1);
            if (const auto frustum = math::shadowFrustum(input, light, s.mapSize)) {
                s.cubeMap = frustum->cube;
                s.perspectiveMap = frustum->perspective;
                s.texelSize = frustum->texelSize;
            }
        }
        lights.push_back(s);
    }
    return lights;
}

glm::dvec3 Shader::shade(const Material& m, const MaterialTextures& textures, const Hit& surfaceHit,
                         const glm::dvec3& viewDir, ShadingTerms* terms) const {
    glm::dvec3 base = m.color * glm::dvec3(surfaceHit.color);
    if (textures.base >= 0)
        base *= glm::dvec3(m_textures[textures.base].sample(surfaceHit.uv, m.wrap[0], m.wrap[1]));
    glm::dvec3 emitted = m.emission;
    if (textures.emission >= 0)
        emitted *= glm::dvec3(m_textures[textures.emission].sample(surfaceHit.uv, m.wrap[0], m.wrap[1]));
    // material.glsl's materialNormal(): the tangent made orthogonal to the viewer-side normal,
    // B = w·(n × T), the map's xy scaled. Lighting and the shadow lookup both use the bent normal.
    Hit hit = surfaceHit;
    if (textures.normal >= 0 && surfaceHit.tangent.w != 0.0) {
        const glm::dvec3 n = surfaceHit.normal;
        glm::dvec3 t = glm::dvec3(surfaceHit.tangent) - n * glm::dot(n, glm::dvec3(surfaceHit.tangent));
        const double tLength = glm::length(t);
        if (tLength > 1e-8) {
            t /= tLength;
            const glm::dvec3 b = (surfaceHit.tangent.w < 0.0 ? -1.0 : 1.0) * glm::cross(n, t);
            glm::dvec3 mapped =
                glm::dvec3(m_textures[textures.normal].sample(surfaceHit.uv, m.wrap[0], m.wrap[1])) * 2.0 -
                1.0;
            mapped.x *= m.normalScale;
            mapped.y *= m.normalScale;
            const glm::dvec3 bent = t * mapped.x + b * mapped.y + n * mapped.z;
            const double bentLength = glm::length(bent);
            if (bentLength > 1e-8 && std::isfinite(bentLength))
                hit.normal = bent / bentLength;
        }
    }
    const glm::dvec3& n = hit.normal;
    const double shininess = std::max(m.shininess, 1e-3);
    glm::dvec3 diffuse(0.0), specular(0.0);
    for (std::size_t index = 0; index < m_lights.size(); ++index) {
        const ShadingLight& light = m_lights[index];
        glm::dvec3 toLight;
        double distance = std::numeric_limits<double>::infinity();
        double cone = 1.0;
        if (light.type == LightType::Directional) {
            toLight = -light.direction;
        } else {
            const glm::dvec3 d = light.position - hit.position;
            distance = glm::length(d);
            if (!(distance > 0.0) || !std::isfinite(distance))
                continue; // the light sits on the point: no direction to light it from
            toLight = d / distance;
            if (light.type == LightType::Spot)
                cone = smoothstep(light.cosOuter, light.cosInner, glm::dot(-toLight, light.direction));
        }
        const double nDotL = glm::dot(n, toLight);
        LightTerm* term = nullptr;
        if (terms) {
            terms->lights.push_back(
                {.light = int(index), .nDotL = nDotL, .cone = cone, .shadowed = light.shadowed});
            term = &terms->lights.back();
        }
        if (nDotL <= 0.0 || cone <= 0.0)
            continue;
        double visible = cone;
        if (light.shadowed)
            visible *= visibility(light, hit, toLight, distance);
        if (term)
            term->visibility = cone > 0.0 ? visible / cone : 0.0;
        if (visible <= 0.0)
            continue;
        glm::dvec3 halfway = toLight + viewDir;
        const double halfLength = glm::length(halfway);
        halfway = halfLength > 1e-12 ? halfway / halfLength : n;
        const glm::dvec3 lightDiffuse = light.radiance * nDotL * visible;
        const glm::dvec3 lightSpecular =
            light.radiance * std::pow(std::max(glm::dot(n, halfway), 0.0), shininess) * visible;
        diffuse += lightDiffuse;
        specular += lightSpecular;
        if (term) {
            term->diffuse = base * m.diffuse * lightDiffuse;
            term->specular = m.specular * m.specularColor * lightSpecular;
        }
    }
    const glm::dvec3 total = emitted + base * (m.ambient * m_sceneAmbient + m.diffuse * diffuse) +
                             m.specular * m.specularColor * specular;
    if (terms) {
        terms->normal = n;
        terms->base = base;
        terms->emitted = emitted;
        terms->ambient = base * (m.ambient * m_sceneAmbient);
        terms->total = total;
    }
    return total;
}

double Shader::visibility(const ShadingLight& light, const Hit& hit, const glm::dvec3& toLight,
                          double distanceToLight) const {
    if (m_shadows == ShadowMode::PcfFootprint && light.texelSize > 0.0)
        return pcfVisibility(light, hit, toLight, distanceToLight);
    // Hard: one ray from just off the surface, on the light's side of the triangle.
    const glm::dvec3 side =
        glm::dot(hit.geometricNormal, toLight) >= 0.0 ? hit.geometricNormal : -hit.geometricNormal;
    const double eps = SceneGeometry::offset(hit.position);
    const glm::dvec3 origin = hit.position + side * eps;
    const double tfar = std::isfinite(distanceToLight) ? distanceToLight - 2.0 * eps
                                                       : std::numeric_limits<double>::infinity();
    return m_geometry.occluded(origin, toLight, 0.0, tfar) ? 0.0 : 1.0;
}

double Shader::pcfVisibility(const ShadingLight& light, const Hit& hit, const glm::dvec3& toLight,
                             double distanceToLight) const {
    const int kernel = std::max(light.pcf, 1);
    const double halfKernel = (kernel - 1) * 0.5;
    const bool directional = light.type == LightType::Directional;
    const double distance = directional ? 1.0 : distanceToLight;
    const double texel = light.texelSize * (light.perspectiveMap ? distance : 1.0);
    // lighting.glsl's offsets: 1.5 texels along the normal, and towards the light in proportion to the
    // slope, so the footprint starts where the map's lookup does.
    const double cosTheta = std::clamp(glm::dot(hit.normal, toLight), 0.05, 1.0);
    const double tanTheta = std::sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
    const glm::dvec3 p = hit.position + hit.normal * (1.5 * texel) +
                         toLight * (texel * (halfKernel + 1.0) * std::min(tanTheta, 8.0));
    const glm::dvec3 fromLight = directional ? -toLight : p - light.position;
    if (!(glm::length(fromLight) > 0.0))
        return 1.0;
    glm::dvec3 u, v;
    across(fromLight, u, v);
    // A cube face's texel at the lookup distance; 2D maps: the world texel computed above.
    const double step = light.cubeMap ? glm::length(fromLight) * 2.0 / light.mapSize : texel;
    int lit = 0;
    for (int j = 0; j < kernel; ++j)
        for (int i = 0; i < kernel; ++i) {
            const glm::dvec3 q = p + (u * (i - halfKernel) + v * (j - halfKernel)) * step;
            if (directional) {
                if (!m_geometry.occluded(q, toLight, 0.0, std::numeric_limits<double>::infinity()))
                    ++lit;
                continue;
            }
            const glm::dvec3 d = light.position - q;
            const double length = glm::length(d);
            if (!(length > 0.0) || !m_geometry.occluded(q, d / length, 0.0, length * (1.0 - 1e-6)))
                ++lit;
        }
    return double(lit) / double(kernel * kernel);
}

} // namespace speculum::render::reference
