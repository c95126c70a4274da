// A mirror's own surface over its reflection. Stencil technique: the reflection is already in the
// framebuffer, and dual-source blending computes  surface·(1−R) + reflection·(R·tint)  in one pass.
// Texture technique: the reflection is looked up projectively in the mirror's render texture, sharp, or
// blurred over the GGX lobe of a rough mirror (glossyReflection below).
#include "material.glsl"
#include "hammersley.glsl"
#include "ggx_albedo.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

uniform float uReflectivity;
uniform vec3 uTint;
uniform int uFresnel;
uniform int uFromTexture;
// Stencil technique, pre-weighted (FramePlan::preWeighted): the reflection in the buffer already has its
// weight, and the surface is added over it.
uniform int uReflectionPreWeighted;
uniform sampler2D uReflectionTexture; // rgb: the reflection; alpha: its path length (material.glsl)
uniform vec2 uTargetSize;
uniform float uBlurLod;   // the Mip filter: one lookup at this level
uniform int uGlossyTaps;  // the Footprint filter: lobe samples per pixel; 0: the Mip filter (or sharp)
uniform float uGgxAlpha;  // roughness²
uniform float uRoughness; // 0: a sharp mirror, whose reflection keeps its energy
uniform float uFocalPx;   // pixels per unit of lateral offset at unit distance (the camera's focal length)
uniform float uMaxLod;    // the reflection texture's last mip level
uniform float uChainSigma; // > 0: the Chain filter, the lobe's deviation in tan 2θh per unit of α
uniform vec2 uChainTail;   // the lobe's tail: its deviation as a multiple of the core's, and its weight
uniform vec2 uChainTapsAbove; // the Chain filter blends from its Gaussians to taps between these roughnesses
uniform int uChainTaps;       // and reads this many taps from there on
uniform mat4 uViewProjection; // the parent view's (mesh.vert's), to find the mirror normal on screen
uniform mat4 uReflection;

// Each mirror's draw names its technique, filter and surface (passes::drawMirrorSurface), so a SIMD
// rasterizer such as llvmpipe, which runs both sides of a branch on a uniform under a mask, does not pay
// for the GGX taps or the surface's lighting on a sharp, fully reflective mirror. Without the defines (the
// general shader) the uniforms decide.
#ifdef MIRROR_FROM_TEXTURE
#define MIRROR_USES_TEXTURE (MIRROR_FROM_TEXTURE != 0)
#else
#define MIRROR_USES_TEXTURE (uFromTexture != 0)
#endif
#ifdef MIRROR_GLOSSY_TAPS
#define MIRROR_USES_GLOSSY_TAPS (MIRROR_GLOSSY_TAPS != 0)
#else
#define MIRROR_USES_GLOSSY_TAPS (uGlossyTaps > 0)
#endif
#ifdef MIRROR_CHAIN
#define MIRROR_USES_CHAIN (MIRROR_CHAIN != 0)
#else
#define MIRROR_USES_CHAIN (uChainSigma > 0.0)
#endif
// The chain's two reads (chainReflection): a draw whose roughness takes only one compiles the other out.
#ifdef MIRROR_CHAIN_GAUSSIANS
#define MIRROR_CHAIN_READS_GAUSSIANS (MIRROR_CHAIN_GAUSSIANS != 0)
#define MIRROR_CHAIN_READS_TAPS (MIRROR_CHAIN_TAPS != 0)
#else
#define MIRROR_CHAIN_READS_GAUSSIANS true
#define MIRROR_CHAIN_READS_TAPS true
#endif
#ifdef MIRROR_FRESNEL
#define MIRROR_USES_FRESNEL (MIRROR_FRESNEL != 0)
#else
#define MIRROR_USES_FRESNEL (uFresnel != 0)
#endif
// 1: a sharp mirror (roughness 0): each pixel reads its own texel of the reflection, which a fetch gives
// exactly (the pixel's centre is the texel's), without the filtered lookup's work.
#ifdef MIRROR_SHARP
#define MIRROR_READS_OWN_TEXEL (MIRROR_SHARP != 0)
#else
#define MIRROR_READS_OWN_TEXEL false
#endif
// 1: a sharp mirror whose weight is exactly 1 everywhere (reflectivity 1, white tint, no Fresnel, in a
// view of weight 1): the pixel is its texel, already storable (every colour written into a reflection
// texture was), so none of the arithmetic below runs: on llvmpipe it is a third of the surface's cost.
#ifdef MIRROR_COPY
#define MIRROR_COPIES_TEXEL (MIRROR_COPY != 0)
#else
#define MIRROR_COPIES_TEXEL false
#endif
// 1: the texel to copy is stored sRGB-encoded, as the 8-bit buffer it is copied into stores it, and is
// read as stored through the sampler (nearest, its decode skipped); texelFetch would decode it regardless.
#ifdef MIRROR_COPY_ENCODED
#define MIRROR_COPIES_ENCODED (MIRROR_COPY_ENCODED != 0)
#else
#define MIRROR_COPIES_ENCODED false
#endif
// 0: the mirror reflects everything (reflectivity 1), so its surface is never seen.
#ifdef MIRROR_SURFACE
#define MIRROR_SHOWS_SURFACE (MIRROR_SURFACE != 0)
#else
#define MIRROR_SHOWS_SURFACE true
#endif

layout(location = 0, index = 0) out vec4 fragColor;
layout(location = 0, index = 1) out vec4 reflectionWeight;

const float kPi = 3.14159265358979;

vec2 toPixels(vec3 p) {
    vec4 clip = uViewProjection * (uReflection * vec4(p, 1.0));
    return (clip.xy / clip.w * 0.5 + 0.5) * uTargetSize;
}

// The reflection of a rough mirror: the GGX lobe's microfacet normals, sampled on a Hammersley set turned
// per pixel, each sends the reflected ray off by twice its tilt (tan 2θh): within the plane of incidence
// fully, across it scaled by cos θ (the glossy streak that stretches towards the viewer at grazing angles).
// A ray that meets the scene a distance d beyond the mirror, with the whole path L long, lands
// (d / L)·tan 2θh away on screen. Each tap reads the mip level that covers its share of the footprint.
// Approximations (what the bench measures against the tracer): one distance for the whole footprint (that
// of the sharp reflection at this pixel, so a near object's edge takes the far background's blur), offsets
// that treat the tilts along and across the plane of incidence apart, tilts capped at tan θh = 0.9, and
// microfacet normals sampled by D alone, equally weighted.
struct Footprint {
    float scale;    // pixels per unit of tan 2θh
    float cosView;  // at least 0.02
    vec2 along;     // the plane of incidence on screen (unit)
    vec2 across;
};

Footprint lobeFootprint(vec2 uv, vec3 normal, vec3 viewDir) {
    // The pixel's own texel (its centre is the pixel's): a fetch, without a filtered lookup's work.
    vec4 sharp = texelFetch(uReflectionTexture, ivec2(gl_FragCoord.xy), 0);
    float eyeDistance = length(vWorld - uEye);
    float pathLength = max(sharp.a, eyeDistance);
    float beyond = pathLength - eyeDistance;
    Footprint f;
    f.cosView = clamp(dot(normal, viewDir), 0.02, 1.0);
    f.scale = uFocalPx * beyond / pathLength;
    // The plane of incidence on screen: where the normal points from this pixel.
    vec2 along = toPixels(vWorld + normal * (0.05 * eyeDistance)) - gl_FragCoord.xy;
    f.along = dot(along, along) > 1e-6 ? normalize(along) : vec2(0.0, 1.0);
    f.across = vec2(-f.along.y, f.along.x);
    return f;
}

// `count` taps over the lobe (uGlossyTaps for the Footprint filter; the Chain filter's rough end reads
// uChainTaps of them from its convolved levels).
vec3 lobeTaps(vec2 uv, Footprint f, int count) {
    float scale = f.scale, cosView = f.cosView;
    vec2 along = f.along, across = f.across;
    float taps = float(count);
    float footprintArea = kPi * (2.0 * scale * uGgxAlpha) * (2.0 * scale * uGgxAlpha) * cosView;
    float lod = clamp(0.5 * log2(max(footprintArea / taps, 1.0)), 0.0, uMaxLod);
    // Interleaved gradient noise: a rotation per pixel trades the sample pattern's ghosts for noise.
    float turn = 2.0 * kPi * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    vec3 sum = vec3(0.0);
    for (int k = 0; k < count; ++k) {
        float u1 = (float(k) + 0.5) / taps;
        float u2 = radicalInverse(uint(k));
        // GGX: tan²θh = α² u / (1 − u); the reflection turns by 2θh. Capped: the lobe's far tail would
        // land beyond the texture.
        float t = min(uGgxAlpha * sqrt(u1 / (1.0 - u1)), 0.9);
        float spread = 2.0 * t / (1.0 - t * t);
        float phi = 2.0 * kPi * u2 + turn;
        vec2 tilt = spread * vec2(cos(phi), sin(phi) * cosView);
        vec2 offset = scale * (tilt.x * along + tilt.y * across);
        sum += textureLod(uReflectionTexture, uv + offset / uTargetSize, lod).rgb;
    }
    return sum / taps;
}

vec3 glossyReflection(vec2 uv, vec3 normal, vec3 viewDir) {
    return lobeTaps(uv, lobeFootprint(uv, normal, viewDir), uGlossyTaps);
}

// The Chain filter, up to roughness uChainTapsAbove.x: the lobe as two Gaussians in tan 2θh (a core of
// deviation uChainSigma·α and a wider tail, uChainTail), each of that deviation along the plane of
// incidence and cos θ times it across (the footprint's stretch), read from the convolved chain
// (shaders/mip_convolve.frag: level k is a Gaussian of variance (4^k − 1)/4 texels²) at the level of the
// narrower axis, twice, ±d along the plane of incidence, so that the two lookups spread the rest of the
// stretch (d² + the level's variance = the variance along). Four lookups a pixel.
// One Gaussian of deviation sigmaAlong (pixels) along the plane of incidence, in two lookups.
vec3 chainLookups(vec2 uv, Footprint f, float sigmaAlong) {
    float sigmaLevel = max(sigmaAlong * f.cosView, 0.6 * sigmaAlong);
    float lod = clamp(0.5 * log2(4.0 * sigmaLevel * sigmaLevel + 1.0), 0.0, uMaxLod);
    float d = sqrt(max(sigmaAlong * sigmaAlong - sigmaLevel * sigmaLevel, 0.0));
    vec2 offset = f.along * d / uTargetSize;
    return 0.5 * (textureLod(uReflectionTexture, uv + offset, lod).rgb +
                  textureLod(uReflectionTexture, uv - offset, lod).rgb);
}

vec3 chainGaussians(vec2 uv, Footprint f) {
    float core = f.scale * uChainSigma * uGgxAlpha; // pixels
    vec3 narrow = chainLookups(uv, f, core);
    vec3 wide = chainLookups(uv, f, core * uChainTail.x);
    return mix(narrow, wide, uChainTail.y);
}

// Rougher, the lobe's wide share turns the ray off the screen, where the reflection texture has nothing:
// a Gaussian that wide reads the coarsest levels, which spread what is on screen over all of it (6 dB off
// the tracer at roughness 0.6), where the lobe's taps, clamped at the texture's edge, read what lies along
// it. From uChainTapsAbove.y on, the chain reads uChainTaps taps of the lobe from its convolved levels,
// whose Gaussian blur fills between the taps better than the plain mip chain does; in between, both,
// blended, so that a roughness slider shows no jump.
vec3 chainReflection(vec2 uv, vec3 normal, vec3 viewDir) {
    Footprint f = lobeFootprint(uv, normal, viewDir);
    float taps = clamp((uRoughness - uChainTapsAbove.x) / (uChainTapsAbove.y - uChainTapsAbove.x), 0.0, 1.0);
    vec3 sum = vec3(0.0);
    if (MIRROR_CHAIN_READS_GAUSSIANS && taps < 1.0)
        sum += (1.0 - taps) * chainGaussians(uv, f);
    if (MIRROR_CHAIN_READS_TAPS && taps > 0.0)
        sum += taps * lobeTaps(uv, f, uChainTaps);
    return sum;
}

void main() {
    if (MIRROR_COPIES_TEXEL) {
        vec3 texel = MIRROR_COPIES_ENCODED ? textureLod(uReflectionTexture, gl_FragCoord.xy / uTargetSize, 0.0).rgb
                                           : texelFetch(uReflectionTexture, ivec2(gl_FragCoord.xy), 0).rgb;
        fragColor = vec4(texel, outputAlpha(vWorld));
        reflectionWeight = vec4(0.0);
        return;
    }
    vec3 normal = normalize(vNormal);
    vec3 viewDir = normalize(uEye - vWorld);
    float r = uReflectivity;
    if (MIRROR_USES_FRESNEL) {
        // Schlick's approximation with the reflectivity as the value at normal incidence.
        float c = clamp(dot(normal, viewDir), 0.0, 1.0);
        r = r + (1.0 - r) * pow(1.0 - c, 5.0);
    }
    vec3 surface = vec3(0.0);
    if (MIRROR_SHOWS_SURFACE && r < 1.0)
        surface = shadeMaterial(vWorld, normal, vUv) * (1.0 - r);
    vec3 weight = uTint * r;
    float alpha = outputAlpha(vWorld);
    if (MIRROR_USES_TEXTURE) {
        vec2 uv = gl_FragCoord.xy / uTargetSize;
        vec3 reflection = MIRROR_READS_OWN_TEXEL ? texelFetch(uReflectionTexture, ivec2(gl_FragCoord.xy), 0).rgb
                          : MIRROR_USES_GLOSSY_TAPS ? glossyReflection(uv, normal, viewDir)
                          : MIRROR_USES_CHAIN       ? chainReflection(uv, normal, viewDir)
                                                    : textureLod(uReflectionTexture, uv, uBlurLod).rgb;
        // A rough mirror loses what its microfacets mask and shadow, as the tracer's lobe samples do.
        if (!MIRROR_READS_OWN_TEXEL && uRoughness > 0.0)
            reflection *= ggxAlbedo(dot(normal, viewDir), uRoughness);
        fragColor = vec4(storableRadiance((surface + weight * reflection) * uViewWeight), alpha);
        reflectionWeight = vec4(0.0);
    } else {
        fragColor = vec4(storableRadiance(surface * uViewWeight), alpha);
        // A NaN weight (reflectivity or tint) would make NaN of the reflection already in the buffer.
        reflectionWeight = uReflectionPreWeighted != 0 ? vec4(1.0) : vec4(storableRadiance(weight), 0.0);
    }
}
