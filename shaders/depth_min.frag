// One level of the screen-space depth pyramid: each texel the nearest of the texels of the level below it
// covers. A level is half the one below rounded down, so on an odd axis the last texel also covers the
// third texel left over, and nothing of the level below goes unseen (the trace's skips rely on it).
uniform sampler2D uSource; // only the level below is visible (base = max level), filtered nearest
uniform vec2 uSourceSize; // that level's texels (whole numbers)

out vec4 fragColor;

void main() {
    ivec2 below = ivec2(uSourceSize);
    ivec2 here = max(below / 2, ivec2(1));
    ivec2 cell = ivec2(gl_FragCoord.xy);
    ivec2 first = cell * 2;
    // The texels of the level below this one covers: two on an axis, three for the last on an odd one.
    ivec2 last = min(first + 1 + ivec2(equal(cell, here - 1)) * (below - 2 * here), below - 1);
    vec2 texel = 1.0 / uSourceSize;
    float nearest = 3.0e38;
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x)
            nearest = min(nearest, textureLod(uSource, (vec2(x, y) + 0.5) * texel, 0.0).r);
    fragColor = vec4(nearest, 0.0, 0.0, 1.0);
}
