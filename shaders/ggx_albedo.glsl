// The GGX lobe's directional albedo E(μ_v, roughness) (render/math/GgxAlbedoTable.hpp): the share of a
// blurred reflection that the microfacets' masking and shadowing leave. A blur alone keeps all of it, so
// every glossy path multiplies by this. Read bilinearly between the table's nodes, which lie on the texel
// centres (μ_v along x, roughness along y, both 0 to 1).
#ifndef GGX_ALBEDO_GLSL
#define GGX_ALBEDO_GLSL

uniform sampler2D uGgxAlbedo;

float ggxAlbedo(float cosView, float roughness) {
    vec2 size = vec2(textureSize(uGgxAlbedo, 0));
    vec2 node = clamp(vec2(cosView, roughness), 0.0, 1.0) * (size - 1.0);
    return textureLod(uGgxAlbedo, (node + 0.5) / size, 0.0).r;
}

#endif
