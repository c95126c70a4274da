// A mirror's own surface over its reflection. Stencil technique: the reflection is already in the
// framebuffer, and dual-source blending computes  surface·(1−R) + reflection·(R·tint)  in one pass.
// Texture technique: the reflection is looked up projectively in the mirror's render texture.
#include "material.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

uniform float uReflectivity;
uniform vec3 uTint;
uniform int uFresnel;
uniform int uFromTexture;
uniform sampler2D uReflectionTexture;
uniform vec2 uTargetSize;
uniform float uBlurLod;

layout(location = 0, index = 0) out vec4 fragColor;
layout(location = 0, index = 1) out vec4 reflectionWeight;

void main() {
    vec3 normal = normalize(vNormal);
    vec3 viewDir = normalize(uEye - vWorld);
    float r = uReflectivity;
    if (uFresnel != 0) {
        // Schlick's approximation with the reflectivity as the value at normal incidence.
        float c = clamp(dot(normal, viewDir), 0.0, 1.0);
        r = r + (1.0 - r) * pow(1.0 - c, 5.0);
    }
    vec3 surface = r < 1.0 ? shadeMaterial(vWorld, normal, vUv) * (1.0 - r) : vec3(0.0);
    vec3 weight = uTint * r;
    if (uFromTexture != 0) {
        vec3 reflection = textureLod(uReflectionTexture, gl_FragCoord.xy / uTargetSize, uBlurLod).rgb;
        fragColor = vec4(storableRadiance(surface + weight * reflection), 1.0);
        reflectionWeight = vec4(0.0);
    } else {
        fragColor = vec4(storableRadiance(surface), 1.0);
        // A NaN weight (reflectivity or tint) would make NaN of the reflection already in the buffer.
        reflectionWeight = vec4(storableRadiance(weight), 0.0);
    }
}
