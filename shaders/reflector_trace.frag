// The curved reflector traced in screen space first (ReflectorTechnique::ScreenSpace): drawn over the
// reflector the main pass drew with its environment map, each pixel's reflected ray is traced through the
// camera's image (shaders/screen_trace.glsl); where it meets what the image shows, that replaces the map's
// lookup, which has the parallax error of a map captured from one point; where it does not, the map stays.
// The pass adds the difference, weighted as reflector.frag weighs its reflection (reflectivity, Schlick's
// Fresnel): surface·(1 − r) + map·r becomes surface·(1 − r) + (hit·c + map·(1 − c))·r, so what the main
// pass drew is kept wherever the trace adds nothing. A rough reflector traces its lobe's central ray and
// reads what it meets from the image's blurred pyramid at the cone's width there (imageSeen), against the
// map's rough lookup; both take the lobe's albedo, as reflector.frag's rough lookups do.
#include "screen_trace.glsl"
#include "ggx_albedo.glsl"

in vec3 vView;
in vec3 vNormalView;

uniform float uReflectivity;
uniform int uFresnel;
uniform float uOriginOffset; // view-space distance per unit of eye distance that clears the surface itself
uniform vec3 uViewWeight;    // what the camera's buffer keeps of its view (reflector.frag's, 1 but in pre-weighted frames)

out vec4 fragColor;

void main() {
    vec3 p = vView;
    float eyeDistance = max(length(p), 1e-30);
    vec3 N = normalize(vNormalView);
    if (!gl_FrontFacing)
        N = -N;
    vec3 E = -p / eyeDistance;
    vec3 r = envmapReflection(E, N); // reflector.frag's reflection, so the map's lookup is the same
    // What the surface drew from the map, looked up as reflector.frag does (camera-relative world space),
    // outside every branch: the lookup takes derivatives of its direction.
    vec3 drawn = reflectorEnvironment(uWorldFromView * p, uWorldFromView * r);
    // Off the surface by a pixel or two, so that the ray does not meet the pixels it starts from.
    vec3 origin = p + N * (uOriginOffset * eyeDistance);
    // The GGX lobe, about 2.6 α wide at half its peak: the half-vector's density halves at tan θ = 0.64 α,
    // and the reflection turns by twice the half-vector's angle.
    float spread = REFLECTOR_LOOKUP != 0 ? 2.6 * uRoughness * uRoughness : 0.0;
    Reflection reflection = traceReflection(p, origin, normalize(r), eyeDistance, vec4(drawn, uFarPath), spread);
    if (uShowSources != 0) {
        fragColor = vec4(sourceColour(reflection.confidence), 0.0);
        return;
    }
    float weight = uReflectivity;
    if (uFresnel != 0) {
        float c = clamp(dot(N, E), 0.0, 1.0);
        weight = weight + (1.0 - weight) * pow(1.0 - c, 5.0);
    }
    if (REFLECTOR_LOOKUP != 0)
        weight *= ggxAlbedo(dot(N, E), uRoughness);
    fragColor = vec4(storableRadiance(weight * (reflection.colour - reflection.missed) * uViewWeight), 0.0);
}
