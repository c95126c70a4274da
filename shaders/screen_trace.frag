// A screen-space mirror's reflection (MirrorTechnique::ScreenSpace), traced through the camera's own image
// (shaders/screen_trace.glsl) into the mirror's reflection texture, which the mirror's surface pass then
// reads as a texture mirror's (so roughness, Fresnel and tint apply alike).
#include "screen_trace.glsl"

in vec3 vView; // the mirror's point, in the camera's view space

uniform vec3 uNormal; // the mirror's reflective side, in view space

out vec4 fragColor;

void main() {
    vec3 p = vView;
    float eyeDistance = length(p);
    vec3 r = reflect(p / max(eyeDistance, 1e-30), normalize(uNormal));
    // Outside every branch: the map's lookup takes derivatives of its direction. One sharp ray: a rough
    // mirror's surface pass blurs the texture by the path lengths written with it.
    Reflection reflection = traceReflection(p, p, r, eyeDistance, fallback(p, r, eyeDistance), 0.0);
    if (uShowSources != 0) {
        fragColor = vec4(sourceColour(reflection.confidence), 0.0);
        return;
    }
    fragColor = storableRadiance(vec4(reflection.colour, reflection.pathLength));
}
