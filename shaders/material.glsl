// The Blinn-Phong material of DESIGN.md, shared by objects and mirror surfaces.
#include "lighting.glsl"

uniform vec3 uColor;
uniform float uAmbient;
uniform float uDiffuse;
uniform float uSpecular;
uniform float uShininess;
uniform vec3 uEmission;
uniform int uHasTexture;
uniform sampler2D uTexture; // sRGB texture: sampling returns linear values
uniform float uSceneAmbient;
uniform vec3 uEye; // the (virtual) eye, camera-relative and unreflected

vec3 shadeMaterial(vec3 position, vec3 normal, vec2 uv) {
    vec3 viewDir = normalize(uEye - position);
    vec3 base = uColor;
    if (uHasTexture != 0)
        base *= texture(uTexture, uv).rgb;
    SurfaceLight light = shadeLights(position, normal, viewDir, uShininess);
    return uEmission + base * (uAmbient * uSceneAmbient + uDiffuse * light.diffuse) + uSpecular * light.specular;
}
