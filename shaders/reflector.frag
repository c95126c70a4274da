// Pass 2 of the curved reflector: its surface looks the environment map up with the reflection vector.
// Everything is in unreflected, camera-relative world space: inside a planar mirror's view uEye is the
// virtual eye, so the reflector seen in a mirror reflects what it would from there.
#include "material.glsl"
#include "envmap_lookup.glsl"
#include "ggx_albedo.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

uniform samplerCube uEnvCube;   // cube maps
uniform sampler2DArray uEnvArray; // dual-paraboloid and tennis-ball maps
uniform int uEnvType;           // ENVMAP_*
uniform vec4 uEnvLayout;        // MapLayout::packed()
uniform mat3 uEnvMapFromWorld;  // world axes → the map's frame
uniform vec3 uEnvCentre;        // the capture point, camera-relative
uniform float uReflectivity;
uniform int uFresnel;
uniform int uParallax;          // 0 off, 1 sphere, 2 box
uniform float uParallaxRadius;
uniform vec3 uParallaxMin;      // relative to the capture point
uniform vec3 uParallaxMax;
uniform int uRough;             // roughness > 0: one lookup at an explicit LOD in the bound texture
uniform float uRoughnessLod;    // roughness × (levels − 1) of that texture (ReflectorPass::drawSurface)
uniform float uRoughness;

out vec4 fragColor;

// Parallax correction: the point where the reflected ray from the shaded point leaves the proxy, seen
// from the capture point. A ray that never meets the proxy (the point outside it) keeps its direction.
vec3 parallaxDirection(vec3 p, vec3 r) {
    if (uParallax == 1) {
        float b = dot(p, r);
        float c = dot(p, p) - uParallaxRadius * uParallaxRadius;
        float disc = b * b - c;
        float t = -b + sqrt(max(disc, 0.0));
        return (disc >= 0.0 && t > 0.0) ? p + t * r : r;
    }
    vec3 safe = mix(vec3(1e-20), r, greaterThan(abs(r), vec3(1e-20)));
    vec3 t1 = (uParallaxMin - p) / safe;
    vec3 t2 = (uParallaxMax - p) / safe;
    vec3 tFar = max(t1, t2);
    float t = min(tFar.x, min(tFar.y, tFar.z));
    return t > 0.0 ? p + t * r : r;
}

void main() {
    vec3 N = normalize(vNormal);
    if (!gl_FrontFacing)
        N = -N;
    vec3 E = normalize(uEye - vWorld);
    vec3 R = envmapReflection(E, N);
    vec3 dir = uParallax != 0 ? parallaxDirection(vWorld - uEnvCentre, normalize(R)) : R;
    vec3 d = normalize(uEnvMapFromWorld * dir);
    // Screen derivatives of the unit direction: continuous across every seam, unlike those of texture
    // coordinates; the lookups turn them into an explicit LOD.
    vec3 dx = dFdx(d);
    vec3 dy = dFdy(d);
    vec3 environment;
    if (uRough == 0)
        environment = uEnvType == ENVMAP_CUBE ? envmapLookupCube(uEnvCube, d, dx, dy).rgb
                                              : envmapLookup2D(uEnvArray, uEnvType, uEnvLayout, d, dx, dy).rgb;
    else
        // The chain's levels are normalised blurs: the lobe's masking and shadowing come on top.
        environment = (uEnvType == ENVMAP_CUBE ? envmapLookupCubeLod(uEnvCube, d, dx, dy, uRoughnessLod).rgb
                                               : envmapLookup2DLod(uEnvArray, uEnvType, uEnvLayout, d, dx, dy,
                                                                   uRoughnessLod).rgb) *
                      ggxAlbedo(dot(N, E), uRoughness);
    float r = uReflectivity;
    if (uFresnel != 0) {
        // Schlick's approximation with the reflectivity as the value at normal incidence.
        float c = clamp(dot(N, E), 0.0, 1.0);
        r = r + (1.0 - r) * pow(1.0 - c, 5.0);
    }
    vec3 surface = r < 1.0 ? shadeMaterial(vWorld, N, vUv) : vec3(0.0);
    fragColor = vec4(storableRadiance((surface * (1.0 - r) + environment * r) * uViewWeight), outputAlpha(vWorld));
}
