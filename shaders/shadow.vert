// Depth-only shadow maps, and flat-coloured mirror masks. With ENVMAP_WARP defined (mirror masks in the
// environment pass's direct fill) uModelLightClip takes the object to reflected capture-relative
// coordinates instead, which are warped like mesh.vert's and cut by clip distance 0 at the parent mirror.
#ifdef ENVMAP_WARP
#include "envmap_warp.glsl"
uniform vec4 uClipPlane;
#endif

layout(location = 0) in vec3 aPosition;

uniform mat4 uModelLightClip; // object → light clip space

void main() {
#ifdef ENVMAP_WARP
    vec4 drawn = uModelLightClip * vec4(aPosition, 1.0);
    gl_Position = envmapWarp(drawn.xyz);
    gl_ClipDistance[0] = dot(uClipPlane, drawn);
#else
    gl_Position = uModelLightClip * vec4(aPosition, 1.0);
#endif
}
