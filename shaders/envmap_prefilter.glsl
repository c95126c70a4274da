// The GGX pre-filter of a rough reflector's map (render/envmap/Prefilter.hpp): one full-screen pass (with
// fullscreen.vert) per level and face or component writes every texel, guard band included, with the
// source map convolved with the GGX lobe around the texel's direction.
//
// The split-sum assumption (Karis 2013): normal = view = reflection = the texel's direction r, so the lobe
// is the same for every view and one map per roughness serves all of them. GGX half vectors h around r
// come from Hammersley points, l = reflect(−r, h), weighted by n·l. Each sample reads the source at the LOD
// whose texels cover the solid angle the sample stands for (filtered importance sampling, Colbert and
// Křivánek, GPU Gems 3 ch. 20): a few dozen samples then give a smooth lobe instead of fireflies.
//
// Texel directions use the mapping's continuation past a component's nominal square (as the resampled
// fill does), so the guard band holds filtered environment too; the source is read in the component its
// direction belongs to, with the layout's guard band under bilinear and mipmapped reads.
#include "envmap_lookup.glsl"
#include "hammersley.glsl"

uniform samplerCube uSourceCube;      // cube maps
uniform sampler2DArray uSourceArray;  // dual-paraboloid and tennis-ball maps
uniform int uEnvType;                 // ENVMAP_*
uniform int uEnvComponent;            // the cube face or array layer written
uniform vec4 uEnvLayout;              // MapLayout::packed(): the same at every level
uniform vec2 uLevelSize;              // texels of one component at the level written
uniform float uRoughness;             // > 0: α = roughness²
uniform int uSamples;
uniform float uSourceTexelSolidAngle; // steradians of one level-0 source texel (the layout's mean)
uniform float uSourceMaxLod;

out vec4 fragColor;

const float kPi = 3.14159265358979324;

vec3 readSource(vec3 d, float lod) {
    if (uEnvType == ENVMAP_CUBE)
        return textureLod(uSourceCube, d, lod).rgb;
    int component = envmapComponent(uEnvType, d);
    vec2 uv = uEnvLayout.zw + uEnvLayout.xy * envmapUv(uEnvType, component, d);
    return textureLod(uSourceArray, vec3(uv, float(component)), lod).rgb;
}

void main() {
    vec2 t = gl_FragCoord.xy / uLevelSize;
    vec3 n = normalize(uEnvType == ENVMAP_CUBE
                           ? envmapCubeDirection(uEnvComponent, t)
                           : envmapDirection(uEnvType, uEnvComponent, (t - uEnvLayout.zw) / uEnvLayout.xy));
    vec3 up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 tx = normalize(cross(up, n));
    vec3 ty = cross(n, tx);
    float alpha = uRoughness * uRoughness;
    float a2 = alpha * alpha;
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int i = 0; i < uSamples; ++i) {
        float u = float(i) / float(uSamples);
        float v = radicalInverse(uint(i));
        // GGX's inverse CDF in cos²θ of the half vector; φ uniform.
        float cos2 = (1.0 - v) / (1.0 + (a2 - 1.0) * v);
        float cosTheta = sqrt(cos2);
        float sinTheta = sqrt(max(1.0 - cos2, 0.0));
        float phi = 2.0 * kPi * u;
        vec3 h = tx * (sinTheta * cos(phi)) + ty * (sinTheta * sin(phi)) + n * cosTheta;
        vec3 l = 2.0 * dot(n, h) * h - n;
        float nl = dot(n, l);
        if (nl <= 0.0)
            continue;
        // pdf(l) = D(h)·(n·h) / (4·(v·h)) = D(h) / 4 with v = n. The first sample (v = 0) is h = n, l = n:
        // the weight is never zero.
        float q = cos2 * (a2 - 1.0) + 1.0;
        float pdf = a2 / (4.0 * kPi * q * q);
        float sampleSolidAngle = 1.0 / (float(uSamples) * pdf);
        // +1: each sample's footprint overlaps its neighbours' (Colbert and Křivánek's bias).
        float lod = clamp(0.5 * log2(sampleSolidAngle / uSourceTexelSolidAngle) + 1.0, 0.0, uSourceMaxLod);
        sum += readSource(l, lod) * nl;
        weight += nl;
    }
    // A weighted mean: a constant environment stays that constant.
    fragColor = vec4(sum / weight, 1.0);
}
