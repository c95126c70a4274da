// What may be written to the linear colour buffer. It is half float (RGBA16F), whose largest value is
// 65504: a brighter colour (a light of intensity 1e9 is allowed) would be stored as +Inf, and a later
// blend (Inf · 0 where a mirror's weight is zero) or filter makes NaN of it. So every shader that writes
// that buffer passes its colour through storableRadiance, and the composite pass once more: NaN becomes 0
// and the rest is clamped to ±65504. The tracer does the same to its pixels (render/reference/Tracer.cpp),
// so the two renderers agree on over-bright surfaces. The test is on the bits, which no compiler
// optimisation of isnan/isinf can remove.
const float kMaxRadiance = 65504.0;

float storableRadiance(float x) {
    // NaN: all exponent bits set and a non-zero mantissa. ±Inf is left to the clamp.
    uint bits = floatBitsToUint(x);
    bool nan = (bits & 0x7f800000u) == 0x7f800000u && (bits & 0x007fffffu) != 0u;
    return nan ? 0.0 : clamp(x, -kMaxRadiance, kMaxRadiance);
}

vec3 storableRadiance(vec3 c) {
    return vec3(storableRadiance(c.r), storableRadiance(c.g), storableRadiance(c.b));
}

vec4 storableRadiance(vec4 c) {
    return vec4(storableRadiance(c.rgb), storableRadiance(c.a));
}
