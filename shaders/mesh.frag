#include "material.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

out vec4 fragColor;

void main() {
    // Every lookup before the discard: derivatives (mipmap selection) need the whole quad.
    vec4 base = materialBase(vUv);
    vec3 normal = normalize(vNormal);
    // Two-sided: the inside of the teapot's lid gap and the underside of planes are lit as surfaces too.
    // (Reflected passes flip the front face, so this stays right in mirrors.)
    if (!gl_FrontFacing)
        normal = -normal;
    vec3 colour = shadeBase(vWorld, normal, vUv, base.rgb);
    if (materialCutAway(base.a))
        discard;
    fragColor = vec4(storableRadiance(colour * uViewWeight), outputAlpha(vWorld));
}
