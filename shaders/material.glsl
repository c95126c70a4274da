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

// Untextured materials draw with MATERIAL_TEXTURE 0 (passes::setMaterial): a SIMD rasterizer such as
// llvmpipe would otherwise run the lookup under a mask on every pixel.
#ifdef MATERIAL_TEXTURE
#define MATERIAL_HAS_TEXTURE (MATERIAL_TEXTURE != 0)
#else
#define MATERIAL_HAS_TEXTURE (uHasTexture != 0)
#endif

vec3 shadeMaterial(vec3 position, vec3 normal, vec2 uv) {
    vec3 viewDir = normalize(uEye - position);
    vec3 base = uColor;
    if (MATERIAL_HAS_TEXTURE)
        base *= texture(uTexture, uv).rgb;
    SurfaceLight light = shadeLights(position, normal, viewDir, uShininess);
    return uEmission + base * (uAmbient * uSceneAmbient + uDiffuse * light.diffuse) + uSpecular * light.specular;
}
