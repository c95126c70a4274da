// Van der Corput's radical inverse in base 2, the second coordinate of a Hammersley point set: the lobe
// samples of a rough mirror (mirror.frag) and of the reflector's pre-filter (envmap_prefilter.glsl).
// Shifts and masks, because bitfieldReverse needs GLSL 4.00 and these shaders are 3.30.
float radicalInverse(uint bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return float(bits) * 2.3283064365386963e-10; // / 2³²
}
