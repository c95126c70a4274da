// One level of a rough mirror's convolved reflection chain (GlossyFilter::Chain): level k from level k − 1
// (the only level the source's base and max levels leave visible), with the binomial kernel [1 3 3 1]²/64
// over the 4×4 source texels around the destination texel, in four bilinear lookups. Each level adds
// 0.75 source texels² of variance, so level k holds the reflection blurred by a Gaussian of variance
// (4^k − 1)/4 level-0 texels² (mirror.frag's chainLevel inverts this).
uniform sampler2D uSource;

out vec4 fragColor;

void main() {
    vec2 texel = 1.0 / vec2(textureSize(uSource, 0));
    // The destination texel's centre, in source texels, lies between source texels 2x and 2x + 1; a
    // lookup 0.75 of a texel off it on each axis weighs the nearer texel 3 to the farther's 1.
    vec2 centre = gl_FragCoord.xy * 2.0 * texel;
    vec2 d = 0.75 * texel;
    fragColor = 0.25 * (texture(uSource, centre + vec2(-d.x, -d.y)) + texture(uSource, centre + vec2(d.x, -d.y)) +
                        texture(uSource, centre + vec2(-d.x, d.y)) + texture(uSource, centre + vec2(d.x, d.y)));
}
