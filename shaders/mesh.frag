#include "material.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

out vec4 fragColor;

void main() {
    vec3 normal = normalize(vNormal);
    // Two-sided: the inside of the teapot's lid gap and the underside of planes are lit as surfaces too.
    // (Reflected passes flip the front face, so this stays right in mirrors.)
    if (!gl_FrontFacing)
        normal = -normal;
    fragColor = vec4(shadeMaterial(vWorld, normal, vUv), 1.0);
}
