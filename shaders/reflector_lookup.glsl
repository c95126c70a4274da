// The curved reflector's lookup in its environment map: the map's uniforms, and what the surface at a point
// sees along its reflected ray, sharp or through the rough lookups. The reflector's surface
// (reflector.frag) draws it; its screen-space trace (reflector_trace.frag) repeats it exactly, since it
// adds only the difference to what the surface drew; the screen-space mirrors' fallback (screen_trace.glsl)
// reads the same map as a probe.
#ifndef REFLECTOR_LOOKUP_GLSL
#define REFLECTOR_LOOKUP_GLSL
#include "envmap_lookup.glsl"
#include "parallax.glsl"

uniform samplerCube uEnvCube;     // cube maps
uniform sampler2DArray uEnvArray; // dual-paraboloid and tennis-ball maps
uniform int uEnvType;             // ENVMAP_*
uniform vec4 uEnvLayout;          // MapLayout::packed()
uniform mat3 uEnvMapFromWorld;    // world axes → the map's frame
uniform vec3 uEnvCentre;          // the capture point, camera-relative
uniform int uRough;               // roughness > 0: one lookup at an explicit LOD in the bound texture,
                                  // REFLECTOR_MIP_LEVELS or REFLECTOR_GGX_CHAIN
uniform float uRoughnessLod;      // roughness × (levels − 1) of that texture (ReflectorPass::bindLookup)
uniform float uRoughness;

const int REFLECTOR_MIP_LEVELS = 1; // the map's own mip chain: level k is 2^k times coarser
const int REFLECTOR_GGX_CHAIN = 2;  // the pre-filtered chain: level k is the lobe of roughness k / (levels − 1)

// Each draw names its lookup (ReflectorPass::drawSurface), so a SIMD rasterizer such as llvmpipe, which
// runs both sides of a branch on a uniform under a mask, does not pay for the rough lookups on a sharp
// reflector. Without the define (the general shader) the uniform decides.
#ifdef REFLECTOR_ROUGH
#define REFLECTOR_LOOKUP REFLECTOR_ROUGH
#else
#define REFLECTOR_LOOKUP uRough
#endif

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

// What the map shows along the reflected ray R from the point `position` (both camera-relative world
// space), before the lobe's albedo: the sharp lookup, or one at the LOD the roughness asks for. Takes
// screen derivatives: call it in uniform control flow.
vec3 reflectorEnvironment(vec3 position, vec3 R) {
    vec4 hit = uParallax != 0 ? parallaxHit(position - uEnvCentre, normalize(R)) : vec4(R, 0.0);
    vec3 d = normalize(uEnvMapFromWorld * hit.xyz);
    // Screen derivatives of the unit direction: continuous across every seam, unlike those of texture
    // coordinates; the lookups turn them into an explicit LOD.
    vec3 dx = dFdx(d);
    vec3 dy = dFdy(d);
    if (REFLECTOR_LOOKUP == 0)
        return uEnvType == ENVMAP_CUBE ? envmapLookupCube(uEnvCube, d, dx, dy).rgb
                                       : envmapLookup2D(uEnvArray, uEnvType, uEnvLayout, d, dx, dy).rgb;
    if (REFLECTOR_LOOKUP == REFLECTOR_GGX_CHAIN) {
        // Not the mip-level lookups: they would take the pixel's footprint as a level of resolution, which
        // in this chain is a much wider lobe.
        float lod = chainLod(hit, dx, dy);
        return uEnvType == ENVMAP_CUBE ? textureLod(uEnvCube, d, lod).rgb
                                       : envmapLookup2DAtLod(uEnvArray, uEnvType, uEnvLayout, d, lod).rgb;
    }
    return uEnvType == ENVMAP_CUBE
               ? envmapLookupCubeLod(uEnvCube, d, dx, dy, uRoughnessLod).rgb
               : envmapLookup2DLod(uEnvArray, uEnvType, uEnvLayout, d, dx, dy, uRoughnessLod).rgb;
}

#endif
