// Copies the linear colour buffer to the output, sRGB-encoding it for 8-bit targets.
// The one place the rasterizer's output is written: whatever reached the linear buffer (a NaN from a
// blend, an over-bright value), only finite numbers leave (radiance.glsl).
// A preview drawn at a reduced resolution (RenderOptions::resolutionScale) is scaled up here: bilinear
// between the four nearest pixels, each made storable first, so one bad pixel cannot spread NaN.
#include "radiance.glsl"

in vec2 vUv;

uniform sampler2D uColor;
uniform int uEncodeSrgb;
uniform vec2 uSourceScale; // linear-buffer pixels per output pixel; (1, 1): a plain copy

out vec4 fragColor;

// The composite's draw names what it does (passes::runComposite): a SIMD rasterizer such as llvmpipe runs
// both sides of a branch on a uniform under a mask, so a plain copy would otherwise pay for the bilinear
// scale-up and the encoding too. Without the defines the uniforms decide.
#ifdef COMPOSITE_SCALED
#define COMPOSITE_SCALES_UP (COMPOSITE_SCALED != 0)
#else
#define COMPOSITE_SCALES_UP (uSourceScale != vec2(1.0))
#endif
#ifdef COMPOSITE_ENCODE
#define COMPOSITE_ENCODES_SRGB (COMPOSITE_ENCODE != 0)
#else
#define COMPOSITE_ENCODES_SRGB (uEncodeSrgb != 0)
#endif

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

vec4 texel(ivec2 p, ivec2 last) {
    return storableRadiance(texelFetch(uColor, clamp(p, ivec2(0), last), 0));
}

vec4 scaledUp() {
    ivec2 last = textureSize(uColor, 0) - 1;
    // Pixel centres: output centre (x + ½) lands at source coordinate (x + ½)·scale, whose centres lie
    // at integers + ½.
    vec2 p = gl_FragCoord.xy * uSourceScale - 0.5;
    vec2 base = floor(p);
    vec2 f = p - base;
    ivec2 i = ivec2(base);
    vec4 bottom = mix(texel(i, last), texel(i + ivec2(1, 0), last), f.x);
    vec4 top = mix(texel(i + ivec2(0, 1), last), texel(i + ivec2(1, 1), last), f.x);
    return mix(bottom, top, f.y);
}

void main() {
    vec4 c = COMPOSITE_SCALES_UP ? scaledUp() : storableRadiance(texelFetch(uColor, ivec2(gl_FragCoord.xy), 0));
    fragColor = vec4(COMPOSITE_ENCODES_SRGB ? linearToSrgb(c.rgb) : c.rgb, 1.0);
}
