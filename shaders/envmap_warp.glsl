// Pass-1 "direct" fills: the vertex shader warps reflector-relative positions into a dual-paraboloid or
// tennis-ball component. The GLSL twin of warpVertex() in render/envmap/CaptureMath.cpp, where the
// depth (z) terms are derived: with w = 1, the near plane clips what lies behind a paraboloid past its
// guard band, and the far plane clips tennis-ball triangles that straddle the atan branch cut.
// Straight edges become curves: the scene drawn this way must be finely tessellated.
//
// Include from a vertex shader and write gl_Position = envmapWarp(positionRelativeToTheReflector).
// The uniforms are set by envmap::setWarpUniforms (EnvironmentCapture.hpp).
#ifndef ENVMAP_WARP_GLSL
#define ENVMAP_WARP_GLSL

#include "envmap_lookup.glsl"

uniform int uEnvWarpType;      // ENVMAP_DUAL_PARABOLOID or ENVMAP_TENNIS_BALL
uniform int uEnvWarpComponent; // 0 or 1
uniform mat4 uEnvWarpView;     // reflector-relative world → map frame (a rotation)
uniform vec4 uEnvWarpParams;   // xy: NDC scale; paraboloid: z = γ; tennis ball: z = λ, w = κ
uniform float uEnvWarpFar;

vec4 envmapWarpParaboloid(vec3 p, int component, vec2 ndcScale, float rimSine, float far) {
    float rho = max(length(p), 1e-30);
    vec3 d = p / rho;
    float s = component == 0 ? -d.z : d.z;
    float denom = max(1.0 + s, 1e-4); // small only for vertices the near plane clips
    float z = -1.0 + 2.0 * rho * (s + rimSine) / ((1.0 + rimSine) * far);
    return vec4(d.xy / denom * ndcScale, z, 1.0);
}

vec4 envmapWarpTennisBall(vec3 p, int component, vec2 ndcScale, float depthScale, float cutCurvature, float far) {
    float rho = max(length(p), 1e-30);
    vec2 ab = envmapTennisBallUv(component, p / rho) * 2.0 - 1.0;
    float z = -1.0 + depthScale * rho / far + cutCurvature * ab.y * ab.y;
    return vec4(ab * ndcScale, z, 1.0);
}

vec4 envmapWarp(vec3 reflectorRelative) {
    vec3 p = (uEnvWarpView * vec4(reflectorRelative, 1.0)).xyz;
    if (uEnvWarpType == ENVMAP_DUAL_PARABOLOID)
        return envmapWarpParaboloid(p, uEnvWarpComponent, uEnvWarpParams.xy, uEnvWarpParams.z, uEnvWarpFar);
    return envmapWarpTennisBall(p, uEnvWarpComponent, uEnvWarpParams.xy, uEnvWarpParams.z, uEnvWarpParams.w,
                                uEnvWarpFar);
}

#endif
