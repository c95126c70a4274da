// Blinn-Phong with point, directional and spot lights, and shadow maps filtered by percentage-closer
// filtering. Positions are camera-relative world coordinates.
#define MAX_LIGHTS 8
#define LIGHT_POINT 0
#define LIGHT_DIRECTIONAL 1
#define LIGHT_SPOT 2

uniform int uLightCount;
uniform int uLightType[MAX_LIGHTS];
uniform vec3 uLightPosition[MAX_LIGHTS];  // camera-relative
uniform vec3 uLightDirection[MAX_LIGHTS]; // unit, the way the light shines
uniform vec3 uLightRadiance[MAX_LIGHTS];  // colour × intensity
uniform vec2 uLightSpotCos[MAX_LIGHTS];   // cos(outer), cos(inner)
uniform int uLightShadowSlot[MAX_LIGHTS]; // -1: no shadow map

// Four shadow slots. GLSL 3.30 only indexes sampler arrays with constant expressions; with
// ARB_gpu_shader5 (every GL 4 driver, llvmpipe included) the slot, the same for every pixel of a draw,
// indexes them directly. Branching on the slot instead costs four lookups per tap on a SIMD rasterizer
// that runs every branch under a mask (llvmpipe: a third of a lit frame).
uniform sampler2DShadow uShadowMaps[4];
uniform samplerCubeShadow uShadowCubes[4];
uniform mat4 uShadowMatrix[4];      // camera-relative world → light clip space (2D maps)
uniform int uShadowIsCube[4];
uniform int uShadowPerspective[4];
uniform vec2 uShadowNearFar[4];
uniform float uShadowTexelSize[4];  // world texel size (at unit distance for perspective maps)
uniform int uShadowMapSize[4];
uniform int uShadowPcf[4];          // kernel width in texels, 1 = a single hard tap
uniform vec3 uShadowCasterMin[4];   // camera-relative bounds of all the map holds (empty: min above max)
uniform vec3 uShadowCasterMax[4];

// Normal offset in texels: pushes the lookup point off the surface, so slopes don't shadow themselves.
const float kNormalOffsetTexels = 1.5;

float sampleShadow2D(int slot, vec3 coord) {
#ifdef GL_ARB_gpu_shader5
    return texture(uShadowMaps[slot], coord);
#else
    if (slot == 0) return texture(uShadowMaps[0], coord);
    if (slot == 1) return texture(uShadowMaps[1], coord);
    if (slot == 2) return texture(uShadowMaps[2], coord);
    return texture(uShadowMaps[3], coord);
#endif
}

float sampleShadowCube(int slot, vec3 dir, float depth) {
#ifdef GL_ARB_gpu_shader5
    return texture(uShadowCubes[slot], vec4(dir, depth));
#else
    if (slot == 0) return texture(uShadowCubes[0], vec4(dir, depth));
    if (slot == 1) return texture(uShadowCubes[1], vec4(dir, depth));
    if (slot == 2) return texture(uShadowCubes[2], vec4(dir, depth));
    return texture(uShadowCubes[3], vec4(dir, depth));
#endif
}

// Window depth a cube face stores for a point at `dir` from the light: the face's perspective depth
// of the major axis, so the hardware comparison works on a cube map.
float cubeDepth(vec3 dir, vec2 nearFar) {
    float major = max(abs(dir.x), max(abs(dir.y), abs(dir.z)));
    float n = nearFar.x, f = nearFar.y;
    float ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * major);
    return ndc * 0.5 + 0.5;
}

// True when the stretch from `from` along `path`, for t in [0, tEnd], stays out of the box [lo, hi] (slab
// test). A NaN anywhere makes every comparison false: not out, so the caller filters as usual.
bool missesBox(vec3 from, vec3 path, float tEnd, vec3 lo, vec3 hi) {
    // A zero component would give 0·∞ on a slab's face; any tiny one gives the same verdict.
    vec3 safe = mix(path, vec3(1e-30), lessThan(abs(path), vec3(1e-30)));
    vec3 t0 = (lo - from) / safe;
    vec3 t1 = (hi - from) / safe;
    vec3 near = min(t0, t1);
    vec3 far = max(t0, t1);
    float enter = max(max(near.x, near.y), max(near.z, 0.0));
    float leave = min(min(far.x, far.y), min(far.z, tEnd));
    return enter > leave;
}

// Most of what a light reaches lies where no caster can shadow it: every texel the kernel reads there
// holds the cleared depth, and the lookup's answer is 1 before it is made. A tap reads texels within a
// few texels of the lookup point as seen from the light; everything the map holds, nearer the light
// than that point, lies within `reach` of the line from it to the light (a cone narrowing towards the
// light, a cylinder for a directional light). The test is exact, never an approximation: where the line
// meets the casters' box widened by the reach, the kernel is filtered as usual.
bool outOfCastersReach(int slot, bool cube, vec3 p, vec3 lightPosition, vec3 towardsLight, float texel) {
    float reach = texel * (float(max(uShadowPcf[slot], 1)) + 4.0);
    vec3 lo = uShadowCasterMin[slot] - reach;
    vec3 hi = uShadowCasterMax[slot] + reach;
    if (cube || uShadowPerspective[slot] != 0)
        return missesBox(p, lightPosition - p, 1.0, lo, hi);
    return missesBox(p, towardsLight, 3.0e38, lo, hi);
}

float shadowVisibility(int slot, bool cube, vec3 position, vec3 normal, vec3 lightPosition,
                       vec3 towardsLight) {
    int kernel = max(uShadowPcf[slot], 1);
    float halfKernel = float(kernel - 1) * 0.5;
    vec3 toLight = lightPosition - position;
    float distanceToLight = length(toLight);
    float texel = uShadowTexelSize[slot] * (uShadowPerspective[slot] != 0 ? distanceToLight : 1.0);
    // Two offsets keep a surface from shadowing itself: along the normal by a texel and a half, and
    // towards the light in proportion to the slope, because a wide PCF kernel on a surface at a grazing
    // angle to the light compares against depths of the same surface several texels away.
    float cosTheta = clamp(dot(normal, toLight / max(distanceToLight, 1e-6)), 0.05, 1.0);
    float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
    vec3 p = position + normal * (kNormalOffsetTexels * texel) +
             (toLight / max(distanceToLight, 1e-6)) * (texel * (halfKernel + 1.0) * min(tanTheta, 8.0));
    if (outOfCastersReach(slot, cube, p, lightPosition, towardsLight,
                          cube ? length(p - lightPosition) * 2.0 / float(uShadowMapSize[slot]) : texel))
        return 1.0;
    // Most pixels are fully lit or fully shadowed: if the kernel's four corner taps agree, take their
    // verdict and skip the rest (a shadow feature smaller than the kernel between them is missed). The
    // corners' loop has a bound that is not a constant, so it is not unrolled: a SIMD rasterizer that runs
    // every branch under a mask (llvmpipe) still leaves a loop that no pixel enters, and the taps of the
    // pixels that answered above cost nothing where all of their neighbours did too.
    int cornerTaps = kernel > 2 ? 4 : 0;
    float sum = 0.0;
    if (cube) {
        vec3 dir = p - lightPosition;
        // Offsets in the plane perpendicular to the lookup direction, one texel of the face apart.
        vec3 axis = abs(dir.y) < 0.99 * length(dir) ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        vec3 u = normalize(cross(dir, axis));
        vec3 v = cross(normalize(dir), u);
        float step = length(dir) * 2.0 / float(uShadowMapSize[slot]);
        float corners = 0.0;
        for (int c = 0; c < cornerTaps; ++c) {
            vec2 o = vec2(c & 1, c >> 1) * float(kernel - 1) - halfKernel;
            vec3 d = dir + (u * o.x + v * o.y) * step;
            corners += sampleShadowCube(slot, d, cubeDepth(d, uShadowNearFar[slot]));
        }
        if (cornerTaps > 0 && (corners == 0.0 || corners == 4.0))
            return corners * 0.25;
        for (int j = 0; j < kernel; ++j)
            for (int i = 0; i < kernel; ++i) {
                vec3 d = dir + (u * (float(i) - halfKernel) + v * (float(j) - halfKernel)) * step;
                // Each tap's own reference depth: near a cube edge a tap may land on the neighbouring
                // face, whose depth is measured along another axis.
                sum += sampleShadowCube(slot, d, cubeDepth(d, uShadowNearFar[slot]));
            }
    } else {
        vec4 clip = uShadowMatrix[slot] * vec4(p, 1.0);
        vec3 coord = clip.xyz / clip.w * 0.5 + 0.5;
        // Beyond the far plane nothing was drawn into the map; the cone (spot) or the fitted box
        // (directional) decide the lighting there.
        if (coord.z > 1.0) return 1.0;
        vec2 texelUv = vec2(1.0 / float(uShadowMapSize[slot]));
        float corners = 0.0;
        for (int c = 0; c < cornerTaps; ++c) {
            vec2 o = vec2(c & 1, c >> 1) * float(kernel - 1) - halfKernel;
            corners += sampleShadow2D(slot, vec3(coord.xy + o * texelUv, coord.z));
        }
        if (cornerTaps > 0 && (corners == 0.0 || corners == 4.0))
            return corners * 0.25;
        for (int j = 0; j < kernel; ++j)
            for (int i = 0; i < kernel; ++i)
                sum += sampleShadow2D(slot, vec3(coord.xy + vec2(float(i) - halfKernel, float(j) - halfKernel) * texelUv, coord.z));
    }
    return sum / float(kernel * kernel);
}

// GLSL's smoothstep is undefined for equal edges (a spot cone without blend): a step there, as the tracer
// does (render/reference/Shading.cpp).
float coneFactor(vec2 spotCos, float cosAngle) {
    return spotCos.y > spotCos.x ? smoothstep(spotCos.x, spotCos.y, cosAngle) : step(spotCos.x, cosAngle);
}

// The unit vector along d, or zero where there is none: d is scaled by its largest component first, so a
// light 1e19 away (|d|² would overflow a float) still has a direction; a zero d (the light sits on the
// point) or an infinite one gives zero, which lights nothing.
vec3 directionOf(vec3 d) {
    float m = max(abs(d.x), max(abs(d.y), abs(d.z)));
    return m > 0.0 && m < 3.0e38 ? normalize(d / m) : vec3(0.0);
}

struct SurfaceLight {
    vec3 diffuse;
    vec3 specular;
};

// Light i's contribution, added to `result`. `slot` is its shadow map's slot (-1: none) and `cube` the
// map's kind; uLightShadowSlot[i] still says whether the map is there this frame.
void addLight(int i, int type, int slot, bool cube, vec3 position, vec3 normal, vec3 viewDir, float shininess,
              inout SurfaceLight result) {
    vec3 toLight;
    float cone = 1.0;
    if (type == LIGHT_DIRECTIONAL) {
        toLight = -uLightDirection[i];
    } else {
        toLight = directionOf(uLightPosition[i] - position);
        if (type == LIGHT_SPOT)
            cone = coneFactor(uLightSpotCos[i], dot(-toLight, uLightDirection[i]));
    }
    float nDotL = dot(normal, toLight);
    // Written so that a NaN (from a light no reader accepts) lights nothing either.
    if (!(nDotL > 0.0) || !(cone > 0.0))
        return;
    float visibility = cone;
    if (slot >= 0 && uLightShadowSlot[i] >= 0)
        visibility *= shadowVisibility(slot, cube, position, normal, uLightPosition[i], toLight);
    // Light and eye exactly opposite have no halfway vector: the normal, as in the tracer.
    vec3 halfway = directionOf(toLight + viewDir);
    if (halfway == vec3(0.0))
        halfway = normal;
    result.diffuse += uLightRadiance[i] * nDotL * visibility;
    result.specular += uLightRadiance[i] * pow(max(dot(normal, halfway), 0.0), shininess) * visibility;
}

// A SIMD rasterizer (llvmpipe before Mesa 23) runs both sides of a branch on a uniform under a mask, and
// a loop whose bound is a uniform one extra, masked, time. A variant built for the frame's lights
// (render/passes/LightingVariant) therefore names them: LIGHT_COUNT, and per light LIGHT_TYPE_i,
// LIGHT_SLOT_i and LIGHT_CUBE_i. Each light's code appears once, for its own type only, and the other kind
// of shadow lookup not at all. Without them, the shader reads the same from uniforms.
// A variant that does not name a light's type reads it from the uniform.
#ifndef LIGHT_TYPE_0
#define LIGHT_TYPE_0 uLightType[0]
#endif
#ifndef LIGHT_TYPE_1
#define LIGHT_TYPE_1 uLightType[1]
#endif
#ifndef LIGHT_TYPE_2
#define LIGHT_TYPE_2 uLightType[2]
#endif
#ifndef LIGHT_TYPE_3
#define LIGHT_TYPE_3 uLightType[3]
#endif
#ifndef LIGHT_TYPE_4
#define LIGHT_TYPE_4 uLightType[4]
#endif
#ifndef LIGHT_TYPE_5
#define LIGHT_TYPE_5 uLightType[5]
#endif
#ifndef LIGHT_TYPE_6
#define LIGHT_TYPE_6 uLightType[6]
#endif
#ifndef LIGHT_TYPE_7
#define LIGHT_TYPE_7 uLightType[7]
#endif
#define ADD_LIGHT(i, type, slot, cube) \
    addLight(i, type, slot, cube != 0, position, normal, viewDir, shininess, result)

SurfaceLight shadeLights(vec3 position, vec3 normal, vec3 viewDir, float shininess) {
    SurfaceLight result = SurfaceLight(vec3(0.0), vec3(0.0));
#ifdef LIGHT_COUNT
#if LIGHT_COUNT > 0
    ADD_LIGHT(0, LIGHT_TYPE_0, LIGHT_SLOT_0, LIGHT_CUBE_0);
#endif
#if LIGHT_COUNT > 1
    ADD_LIGHT(1, LIGHT_TYPE_1, LIGHT_SLOT_1, LIGHT_CUBE_1);
#endif
#if LIGHT_COUNT > 2
    ADD_LIGHT(2, LIGHT_TYPE_2, LIGHT_SLOT_2, LIGHT_CUBE_2);
#endif
#if LIGHT_COUNT > 3
    ADD_LIGHT(3, LIGHT_TYPE_3, LIGHT_SLOT_3, LIGHT_CUBE_3);
#endif
#if LIGHT_COUNT > 4
    ADD_LIGHT(4, LIGHT_TYPE_4, LIGHT_SLOT_4, LIGHT_CUBE_4);
#endif
#if LIGHT_COUNT > 5
    ADD_LIGHT(5, LIGHT_TYPE_5, LIGHT_SLOT_5, LIGHT_CUBE_5);
#endif
#if LIGHT_COUNT > 6
    ADD_LIGHT(6, LIGHT_TYPE_6, LIGHT_SLOT_6, LIGHT_CUBE_6);
#endif
#if LIGHT_COUNT > 7
    ADD_LIGHT(7, LIGHT_TYPE_7, LIGHT_SLOT_7, LIGHT_CUBE_7);
#endif
#else
    for (int i = 0; i < uLightCount; ++i) {
        int slot = uLightShadowSlot[i];
        addLight(i, uLightType[i], slot, slot >= 0 && uShadowIsCube[max(slot, 0)] != 0, position, normal,
                 viewDir, shininess, result);
    }
#endif
    return result;
}
