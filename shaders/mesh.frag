#include "material.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

out vec4 fragColor;

// A mirror drawn here has no reflection of its own in this view: the depth limit (or the view budget)
// ends its paths. Its front then shows only its surface's share, 1 − R (Schlick's R with uMirrorFresnel),
// and the reflection adds nothing, as the tracer's bounce limit adds nothing; its back is a plain surface.
#ifndef MIRROR_CUT
#define MIRROR_CUT 0
#endif
uniform float uMirrorReflectivity;
uniform int uMirrorFresnel;

float mirrorSurfaceShare(vec3 normal) {
    float r = uMirrorReflectivity;
    if (uMirrorFresnel != 0) {
        float c = clamp(dot(normal, normalize(uEye - vWorld)), 0.0, 1.0);
        r = r + (1.0 - r) * pow(1.0 - c, 5.0);
    }
    return 1.0 - r;
}

void main() {
    // Every lookup before the discard: derivatives (mipmap selection) need the whole quad.
    vec4 base = materialBase(vUv);
    vec3 normal = normalize(vNormal);
    // Two-sided: the inside of the teapot's lid gap and the underside of planes are lit as surfaces too.
    // (Reflected passes flip the front face, so this stays right in mirrors.)
    if (!gl_FrontFacing)
        normal = -normal;
    vec3 colour = shadeBase(vWorld, normal, vUv, base.rgb);
    if (MIRROR_CUT != 0 && gl_FrontFacing)
        colour *= mirrorSurfaceShare(normal);
    if (materialCutAway(base.a))
        discard;
    fragColor = vec4(storableRadiance(colour * uViewWeight), outputAlpha(vWorld));
}
