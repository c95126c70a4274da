// Pass 2 of the curved reflector: its surface looks the environment map up with the reflection vector.
// Everything is in unreflected, camera-relative world space: inside a planar mirror's view uEye is the
// virtual eye, so the reflector seen in a mirror reflects what it would from there.
#include "material.glsl"
#include "envmap_lookup.glsl"
#include "ggx_albedo.glsl"
#include "parallax.glsl"

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
uniform int uRough;             // roughness > 0: one lookup at an explicit LOD in the bound texture,
                                // REFLECTOR_MIP_LEVELS or REFLECTOR_GGX_CHAIN
uniform float uRoughnessLod;    // roughness × (levels − 1) of that texture (ReflectorPass::drawSurface)
uniform float uRoughness;

const int REFLECTOR_MIP_LEVELS = 1; // the map's own mip chain: level k is 2^k times coarser
const int REFLECTOR_GGX_CHAIN = 2;  // the pre-filtered chain: level k is the lobe of roughness k / (levels − 1)

// Each draw names its lookup (ReflectorPass::drawSurface), so a SIMD rasterizer such as llvmpipe, which
// runs both sides of a branch on a uniform under a mask, does not pay for the rough lookups and the
// albedo on a sharp reflector. Without the define (the general shader) the uniform decides.
#ifdef REFLECTOR_ROUGH
#define REFLECTOR_LOOKUP REFLECTOR_ROUGH
#else
#define REFLECTOR_LOOKUP uRough
#endif

out vec4 fragColor;

// The LOD of a lookup in the GGX chain, whose levels are roughnesses (level k: k / (levels − 1)), not
// resolutions: a lookup reads the roughness whose lobe covers both the surface's lobe and the pixel's
// footprint. A lobe's width goes with α = roughness², the two widths add in squares, and the pixel's
// footprint (dd radians of direction a pixel) counts as a lobe of α = dd / 2 (the lobe turns the ray by
// about 2α).
//
// The glossy near field: the chain was filtered as seen from the capture point, a lobe w wide there. From
// the shaded point, the lobe meets the proxy `along` away and covers about along·w of it, which the
// capture point sees `hit` away as an angle (along / hit)·w: the nearer the proxy, the sharper its
// reflection. Without a proxy hit (hit.w = 0), the lobe as captured.
float chainLod(vec4 hit, vec3 dDdx, vec3 dDdy) {
    float alpha = uRoughness * uRoughness;
    if (hit.w > 0.0)
        alpha *= clamp(hit.w / max(length(hit.xyz), 1e-6), 0.0, 1.0);
    float pixel = 0.5 * sqrt(max(dot(dDdx, dDdx), dot(dDdy, dDdy)));
    float roughness = sqrt(sqrt(alpha * alpha + pixel * pixel));
    float levelsBelow = uRoughnessLod / uRoughness; // levels − 1
    return clamp(roughness * levelsBelow, 0.0, levelsBelow);
}

void main() {
    vec3 N = normalize(vNormal);
    if (!gl_FrontFacing)
        N = -N;
    vec3 E = normalize(uEye - vWorld);
    vec3 R = envmapReflection(E, N);
    vec4 hit = uParallax != 0 ? parallaxHit(vWorld - uEnvCentre, normalize(R)) : vec4(R, 0.0);
    vec3 d = normalize(uEnvMapFromWorld * hit.xyz);
    // Screen derivatives of the unit direction: continuous across every seam, unlike those of texture
    // coordinates; the lookups turn them into an explicit LOD.
    vec3 dx = dFdx(d);
    vec3 dy = dFdy(d);
    vec3 environment;
    if (REFLECTOR_LOOKUP == 0) {
        environment = uEnvType == ENVMAP_CUBE ? envmapLookupCube(uEnvCube, d, dx, dy).rgb
                                              : envmapLookup2D(uEnvArray, uEnvType, uEnvLayout, d, dx, dy).rgb;
    } else if (REFLECTOR_LOOKUP == REFLECTOR_GGX_CHAIN) {
        // Not the mip-level lookups: they would take the pixel's footprint as a level of resolution, which
        // in this chain is a much wider lobe.
        float lod = chainLod(hit, dx, dy);
        environment = uEnvType == ENVMAP_CUBE ? textureLod(uEnvCube, d, lod).rgb
                                              : envmapLookup2DAtLod(uEnvArray, uEnvType, uEnvLayout, d, lod).rgb;
    } else {
        environment = uEnvType == ENVMAP_CUBE ? envmapLookupCubeLod(uEnvCube, d, dx, dy, uRoughnessLod).rgb
                                              : envmapLookup2DLod(uEnvArray, uEnvType, uEnvLayout, d, dx, dy,
                                                                  uRoughnessLod).rgb;
    }
    // The chain's levels are normalised blurs: the lobe's masking and shadowing come on top.
    if (REFLECTOR_LOOKUP != 0)
        environment *= ggxAlbedo(dot(N, E), uRoughness);
    float r = uReflectivity;
    if (uFresnel != 0) {
        // Schlick's approximation with the reflectivity as the value at normal incidence.
        float c = clamp(dot(N, E), 0.0, 1.0);
        r = r + (1.0 - r) * pow(1.0 - c, 5.0);
    }
    vec3 surface = r < 1.0 ? shadeMaterial(vWorld, N, vUv) : vec3(0.0);
    fragColor = vec4(storableRadiance((surface * (1.0 - r) + environment * r) * uViewWeight), outputAlpha(vWorld));
}
