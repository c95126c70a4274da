// Main pass: positions are camera-relative world coordinates (camera at the origin), so large world
// coordinates never reach the GPU in single precision. In a mirror's view, geometry is drawn through the
// reflection, but vWorld stays unreflected: lighting is mirrored, not recomputed at the mirrored place.
//
// With ENVMAP_WARP defined this is the environment pass's "direct" fill: the camera-relative origin is
// the capture point, and the (reflected) position is warped into a dual-paraboloid or tennis-ball
// component (envmap_warp.glsl); lighting is unchanged. The warp has no projection to give an oblique near
// plane, so a mirror's reflection is cut at the mirror by clip distance 0 instead (uClipPlane, in
// reflected camera-relative coordinates; the caller enables GL_CLIP_DISTANCE0 when it is used).
#ifdef ENVMAP_WARP
#include "envmap_warp.glsl"
uniform vec4 uClipPlane;
#endif

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aColor;   // constant white where the mesh has none (gl::GpuMesh)
layout(location = 4) in vec4 aTangent; // constant (1, 0, 0, 1) where the mesh has none

uniform mat4 uModel;        // object → camera-relative world
uniform mat3 uNormalMatrix; // inverse transpose of uModel's upper 3×3
uniform mat4 uReflection;   // camera-relative world → camera-relative reflected world (identity: no mirror)
uniform mat4 uViewProjection;

out vec3 vWorld;
out vec3 vNormal;
out vec2 vUv;
out vec4 vColor;
out vec4 vTangent;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    vUv = aUv;
    vColor = aColor;
    // A tangent is a direction in the surface: it transforms like a position. A mirroring transform turns
    // the frame's handedness round, so the bitangent w · (n × t) still points along the mesh's own.
    mat3 linear = mat3(uModel);
    vTangent = vec4(linear * aTangent.xyz, determinant(linear) < 0.0 ? -aTangent.w : aTangent.w);
#ifdef ENVMAP_WARP
    vec4 drawn = uReflection * world;
    gl_Position = envmapWarp(drawn.xyz);
    gl_ClipDistance[0] = dot(uClipPlane, drawn);
#else
    gl_Position = uViewProjection * (uReflection * world);
#endif
}
