// Copies the linear colour buffer to the output, sRGB-encoding it for 8-bit targets.
// The one place the rasterizer's output is written: whatever reached the linear buffer (a NaN from a
// blend, an over-bright value), only finite numbers leave (radiance.glsl).
#include "radiance.glsl"

in vec2 vUv;

uniform sampler2D uColor;
uniform int uEncodeSrgb;

out vec4 fragColor;

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec4 c = storableRadiance(texelFetch(uColor, ivec2(gl_FragCoord.xy), 0));
    fragColor = vec4(uEncodeSrgb != 0 ? linearToSrgb(c.rgb) : c.rgb, 1.0);
}
