// The Blinn-Phong material, shared by objects, mirror surfaces and the reflector
// (render::Material in FrameInput.hpp; render/reference/Shading.cpp is its twin):
//   base     = color · texture.rgb · vertexColor.rgb
//   emitted  = emission · emissionTexture.rgb
//   out      = emitted + base·(ambient·sceneAmbient + diffuse·Σ) + specular·specularColor·Σ
// with the normal taken from a tangent-space normal map where the material has one and the mesh tangents.
#include "lighting.glsl"
#include "radiance.glsl"

uniform vec3 uColor;
uniform float uAmbient;
uniform float uDiffuse;
uniform float uSpecular;
uniform vec3 uSpecularColor;
uniform float uShininess;
uniform vec3 uEmission;
uniform int uHasTexture;
uniform sampler2D uTexture; // sRGB texture: sampling returns linear values
uniform int uHasEmissionTexture;
uniform sampler2D uEmissionTexture; // sRGB
uniform int uHasNormalTexture;
uniform sampler2D uNormalTexture; // data: read as stored
uniform int uHasTangents;         // the mesh being drawn has tangents (a normal map needs them)
uniform float uNormalScale;
uniform float uOpacity;
uniform int uAlphaMask;      // Mask (and Blend, drawn as Mask): discard below uAlphaCutoff
uniform float uAlphaCutoff;
uniform float uSceneAmbient;
uniform vec3 uEye; // the (virtual) eye, camera-relative and unreflected
// Views drawn into a mirror's reflection texture store, in alpha, the length of the path from the camera to
// the point (through the mirrors: the distance from the virtual eye). A rough mirror's blur grows with the
// part of it beyond the mirror (mirror.frag). Every other target keeps alpha 1.
uniform int uPathLengthAlpha;
// What the camera's buffer keeps of this view (passes::ViewSetup::weight): 1, or with pre-weighted stencil
// mirrors the reflectivity × tint of those the view is seen through. Every lit shader's colour is
// multiplied by it as it is written.
uniform vec3 uViewWeight;

// passes::setMaterial names which for its draws (PATH_LENGTH_ALPHA), so the views that keep alpha 1 do not
// pay for the length under a SIMD rasterizer's mask.
#ifdef PATH_LENGTH_ALPHA
#define WRITES_PATH_LENGTH (PATH_LENGTH_ALPHA != 0)
#else
#define WRITES_PATH_LENGTH (uPathLengthAlpha != 0)
#endif

float outputAlpha(vec3 position) {
    return WRITES_PATH_LENGTH ? min(length(position - uEye), 65504.0) : 1.0;
}

in vec4 vColor;   // linear RGBA; white where the mesh has no colours
in vec4 vTangent; // camera-relative world tangent, w = handedness (already signed for mirroring transforms)

// Each feature a material does not use is compiled out for its draws (passes::setMaterial defines it to
// 0): a SIMD rasterizer such as llvmpipe would otherwise run every lookup under a mask on every pixel.
// Without the defines (the general shader) the uniforms decide.
#ifdef MATERIAL_TEXTURE
#define MATERIAL_HAS_TEXTURE (MATERIAL_TEXTURE != 0)
#else
#define MATERIAL_HAS_TEXTURE (uHasTexture != 0)
#endif
#ifdef MATERIAL_EMISSION_TEXTURE
#define MATERIAL_HAS_EMISSION_TEXTURE (MATERIAL_EMISSION_TEXTURE != 0)
#else
#define MATERIAL_HAS_EMISSION_TEXTURE (uHasEmissionTexture != 0)
#endif
#ifdef MATERIAL_NORMAL_TEXTURE
#define MATERIAL_HAS_NORMAL_TEXTURE (MATERIAL_NORMAL_TEXTURE != 0 && uHasTangents != 0)
#else
#define MATERIAL_HAS_NORMAL_TEXTURE (uHasNormalTexture != 0 && uHasTangents != 0)
#endif
#ifdef MATERIAL_ALPHA_MASK
#define MATERIAL_HAS_ALPHA_MASK (MATERIAL_ALPHA_MASK != 0)
#else
#define MATERIAL_HAS_ALPHA_MASK (uAlphaMask != 0)
#endif
// Meshes without colours read constant white; their draws skip the multiply.
#ifdef MATERIAL_VERTEX_COLOR
#define MATERIAL_HAS_VERTEX_COLOR (MATERIAL_VERTEX_COLOR != 0)
#else
#define MATERIAL_HAS_VERTEX_COLOR true
#endif

// Base colour (rgb, linear) and alpha at a point.
vec4 materialBase(vec2 uv) {
    vec4 base = vec4(uColor, uOpacity);
    if (MATERIAL_HAS_TEXTURE)
        base *= texture(uTexture, uv);
    if (MATERIAL_HAS_VERTEX_COLOR)
        base *= vColor;
    return base;
}

// True where a masked material cuts the surface away (the caller discards). Only objects are cut:
// mirrors and the reflector keep their surfaces whole.
bool materialCutAway(float alpha) {
    return MATERIAL_HAS_ALPHA_MASK && alpha < uAlphaCutoff;
}

// The shading normal: `normal` (unit, on the viewer's side) bent by the normal map in the tangent frame
// T (tangent made orthogonal to the normal), B = w · (normal × T), with the map's xy scaled.
vec3 materialNormal(vec3 normal, vec2 uv) {
    if (!MATERIAL_HAS_NORMAL_TEXTURE)
        return normal;
    vec3 t = vTangent.xyz - normal * dot(normal, vTangent.xyz);
    float tLength = length(t);
    if (!(tLength > 1e-8))
        return normal;
    t /= tLength;
    vec3 b = (vTangent.w < 0.0 ? -1.0 : 1.0) * cross(normal, t);
    vec3 m = texture(uNormalTexture, uv).xyz * 2.0 - 1.0;
    m.xy *= uNormalScale;
    vec3 n = t * m.x + b * m.y + normal * m.z;
    float nLength = length(n);
    return nLength > 1e-8 ? n / nLength : normal;
}

vec3 shadeBase(vec3 position, vec3 normal, vec2 uv, vec3 base) {
    vec3 viewDir = normalize(uEye - position);
    vec3 n = materialNormal(normal, uv);
    vec3 emitted = uEmission;
    if (MATERIAL_HAS_EMISSION_TEXTURE)
        emitted *= texture(uEmissionTexture, uv).rgb;
    SurfaceLight light = shadeLights(position, n, viewDir, uShininess);
    return emitted + base * (uAmbient * uSceneAmbient + uDiffuse * light.diffuse) +
           uSpecular * uSpecularColor * light.specular;
}

vec3 shadeMaterial(vec3 position, vec3 normal, vec2 uv) {
    return shadeBase(position, normal, uv, materialBase(uv).rgb);
}
