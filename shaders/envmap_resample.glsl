// The `resampled` fill: one full-screen pass per component (with fullscreen.vert) writes every texel,
// guard band included, with the cube map seen in the texel centre's direction. The direction varies
// smoothly over the texture, so implicit derivatives give the cube's LOD for this texel's footprint.
#include "envmap_lookup.glsl"

uniform samplerCube uEnvCube;
uniform int uEnvType;      // ENVMAP_DUAL_PARABOLOID, ENVMAP_TENNIS_BALL or ENVMAP_OCTAHEDRAL
uniform int uEnvComponent;
uniform vec4 uEnvLayout;   // MapLayout::packed()
uniform vec2 uEnvSize;     // texels of one component
uniform mat3 uEnvWorldFromMap; // map frame → the cube's frame

out vec4 fragColor;

void main() {
    vec2 uv = (gl_FragCoord.xy / uEnvSize - uEnvLayout.zw) / uEnvLayout.xy;
    vec3 d = uEnvWorldFromMap * envmapDirection(uEnvType, uEnvComponent, uv);
    fragColor = vec4(texture(uEnvCube, d).rgb, 1.0);
}
