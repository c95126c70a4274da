// Depth only: the rasterizer writes the depth the comparison sampler reads. Masked casters (SHADOW_MASK)
// leave no depth where their material is cut away: opacity · texture alpha · vertex alpha < cutoff.
#ifdef SHADOW_MASK
in vec2 vUv;
in float vAlpha;
uniform float uOpacity;
uniform float uAlphaCutoff;
uniform int uHasTexture;
uniform sampler2D uTexture;
#endif

void main() {
#ifdef SHADOW_MASK
    float alpha = uOpacity * vAlpha;
    if (uHasTexture != 0)
        alpha *= texture(uTexture, vUv).a;
    if (alpha < uAlphaCutoff)
        discard;
#endif
}
