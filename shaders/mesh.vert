// Main pass: positions are camera-relative world coordinates (camera at the origin), so large world
// coordinates never reach the GPU in single precision. In a mirror's view, geometry is drawn through the
// reflection, but vWorld stays unreflected: lighting is mirrored, not recomputed at the mirrored place.
//
// With ENVMAP_WARP defined this is the environment pass's "direct" fill: the camera-relative origin is
// the capture point, and the position is warped into a dual-paraboloid or tennis-ball component
// (envmap_warp.glsl); lighting is unchanged.
#ifdef ENVMAP_WARP
#include "envmap_warp.glsl"
#endif

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;        // object → camera-relative world
uniform mat3 uNormalMatrix; // inverse transpose of uModel's upper 3×3
uniform mat4 uReflection;   // camera-relative world → camera-relative reflected world (identity: no mirror)
uniform mat4 uViewProjection;

out vec3 vWorld;
out vec3 vNormal;
out vec2 vUv;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    vUv = aUv;
#ifdef ENVMAP_WARP
    gl_Position = envmapWarp(world.xyz);
#else
    gl_Position = uViewProjection * (uReflection * world);
#endif
}
