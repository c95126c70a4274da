// Depth-only shadow maps, and flat-coloured mirror masks. With ENVMAP_WARP defined (mirror masks in the
// environment pass's direct fill) uModelLightClip takes the object to reflected capture-relative
// coordinates instead, which are warped like mesh.vert's and cut by clip distance 0 at the parent mirror.
// With SHADOW_MASK defined (casters whose material has an alpha mask) the uv and the vertex alpha go on to
// shadow.frag, which cuts the same holes as mesh.frag.
#ifdef ENVMAP_WARP
#include "envmap_warp.glsl"
uniform vec4 uClipPlane;
#endif

layout(location = 0) in vec3 aPosition;
#ifdef SHADOW_MASK
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aColor;
out vec2 vUv;
out float vAlpha;
#endif

uniform mat4 uModelLightClip; // object → light clip space

void main() {
#ifdef SHADOW_MASK
    vUv = aUv;
    vAlpha = aColor.a;
#endif
#ifdef ENVMAP_WARP
    vec4 drawn = uModelLightClip * vec4(aPosition, 1.0);
    gl_Position = envmapWarp(drawn.xyz);
    gl_ClipDistance[0] = dot(uClipPlane, drawn);
#else
    gl_Position = uModelLightClip * vec4(aPosition, 1.0);
#endif
}
