// Pass 2 of the curved reflector: its surface looks the environment map up with the reflection vector.
// Everything is in unreflected, camera-relative world space: inside a planar mirror's view uEye is the
// virtual eye, so the reflector seen in a mirror reflects what it would from there.
#include "material.glsl"
#include "ggx_albedo.glsl"
#include "reflector_lookup.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

uniform float uReflectivity;
uniform int uFresnel;

out vec4 fragColor;

void main() {
    vec3 N = normalize(vNormal);
    if (!gl_FrontFacing)
        N = -N;
    vec3 E = normalize(uEye - vWorld);
    vec3 R = envmapReflection(E, N);
    vec3 environment = reflectorEnvironment(vWorld, R);
    // The chain's levels are normalised blurs: the lobe's masking and shadowing come on top.
    if (REFLECTOR_LOOKUP != 0)
        environment *= ggxAlbedo(dot(N, E), uRoughness);
    float r = uReflectivity;
    if (uFresnel != 0) {
        // Schlick's approximation with the reflectivity as the value at normal incidence.
        float c = clamp(dot(N, E), 0.0, 1.0);
        r = r + (1.0 - r) * pow(1.0 - c, 5.0);
    }
    vec3 surface = r < 1.0 ? shadeMaterial(vWorld, N, vUv) : vec3(0.0);
    fragColor = vec4(storableRadiance((surface * (1.0 - r) + environment * r) * uViewWeight), outputAlpha(vWorld));
}
