// A screen-space mirror's reflection (MirrorTechnique::ScreenSpace), traced through the camera's own image
// into the mirror's reflection texture, which the mirror's surface pass then reads as a texture mirror's
// (so roughness, Fresnel and tint apply alike). Each pixel's reflected ray is followed across the image
// through the depth pyramid of minima (shaders/depth_min.frag), hierarchical-Z: where the ray, over a
// cell of some level, stays nearer than everything in it, it skips the cell and climbs a level; otherwise it
// descends, down to single pixels, where it meets the surface the image shows if it has gone behind it by
// less than the thickness. Where it leaves the image, comes back towards the camera, passes behind
// everything it crosses or runs out of steps, the image holds nothing it sees: the background shows, faded
// in towards the image's edges and as the ray turns towards the camera, so that no seam marks the change.
#include "radiance.glsl"

in vec3 vView; // the mirror's point, in the camera's view space

uniform sampler2D uDepthPyramid; // view depth, each level the minimum of the one below (R32F)
uniform sampler2D uImage;        // the camera's linear colour, as every other pass left it
uniform int uLevels;
uniform vec2 uSize;       // the image's pixels
uniform mat4 uProjection; // view → clip
uniform vec3 uNormal;     // the mirror's reflective side, in view space
uniform float uNear;
uniform int uSteps;
uniform float uThickness; // a share of the surface's view depth
uniform vec3 uBackground;
uniform float uFarPath; // the path length of the background (material.glsl's alpha for nothing hit)

out vec4 fragColor;

// The image's pixels of a view-space point, and 1 / its view depth (which the segment interpolates).
vec3 toScreen(vec3 p) {
    vec4 h = uProjection * vec4(p, 1.0);
    float k = 1.0 / h.w;
    return vec3((h.xy * k * 0.5 + 0.5) * uSize, k);
}

// The parameter at which the segment from a to a + d leaves [0, size] on one axis; 1e30 if it never does.
float leaves(float a, float d, float size) {
    if (d > 0.0)
        return (size - a) / d;
    if (d < 0.0)
        return -a / d;
    return 1e30;
}

struct Trace {
    bool hit;
    float t;  // along the screen segment
    vec2 at;  // pixels
};

Trace traceImage(vec3 s0, vec3 s1, float tEnd) {
    vec2 d = s1.xy - s0.xy;
    float perPixel = 1.0 / max(length(d), 1e-6);
    Trace result = Trace(false, 0.0, s0.xy);
    float t = 0.5 * perPixel;
    int level = 0;
    for (int i = 0; i < uSteps && t < tEnd; ++i) {
        vec2 at = s0.xy + d * t;
        float cellSize = exp2(float(level));
        vec2 cell = floor(at / cellSize);
        vec2 boundary = (cell + step(0.0, d)) * cellSize;
        float tExit = min(d.x != 0.0 ? (boundary.x - s0.x) / d.x : 1e30,
                          d.y != 0.0 ? (boundary.y - s0.y) / d.y : 1e30);
        tExit = min(tExit, tEnd);
        float depthIn = 1.0 / mix(s0.z, s1.z, t);
        float depthOut = 1.0 / mix(s0.z, s1.z, tExit);
        // Each level half the one below, rounded down (gl::RenderTexture's chain), computed here: llvmpipe's
        // textureSize misreports the upper levels of a chain whose base level was moved while it was built.
        ivec2 levelSize = max(ivec2(uSize) >> level, ivec2(1));
        float surface = texelFetch(uDepthPyramid, clamp(ivec2(cell), ivec2(0), levelSize - 1), level).r;
        if (max(depthIn, depthOut) < surface) { // in front of everything in the cell: skip it, climb
            t = tExit + 0.02 * perPixel;
            level = min(level + 1, uLevels - 1);
        } else if (level > 0) {
            --level;
        } else if (min(depthIn, depthOut) <= surface * (1.0 + uThickness)) {
            result = Trace(true, t, at);
            break;
        } else { // behind the surface by more than its thickness: the ray passes behind it
            t = tExit + 0.02 * perPixel;
        }
    }
    return result;
}

void main() {
    vec3 p = vView;
    float eyeDistance = length(p);
    vec3 r = reflect(p / max(eyeDistance, 1e-30), normalize(uNormal));
    // Far enough to leave the view; coming back towards the camera, only to just before its near plane.
    float reach = 1e4 * max(eyeDistance, 1.0);
    if (r.z > 1e-6)
        reach = min(reach, 0.99 * (-uNear - p.z) / r.z);
    vec3 q = p + r * max(reach, 0.0);
    vec3 s0 = toScreen(p);
    vec3 s1 = toScreen(q);
    vec2 d = s1.xy - s0.xy;
    float tEnd = min(1.0, min(leaves(s0.x, d.x, uSize.x), leaves(s0.y, d.y, uSize.y)));
    Trace trace = Trace(false, 0.0, s0.xy);
    if (reach > 0.0 && length(d) * tEnd >= 1.0)
        trace = traceImage(s0, s1, tEnd);
    float confidence = 0.0;
    float pathLength = uFarPath;
    vec3 seen = uBackground;
    if (trace.hit) {
        vec2 edge = min(trace.at, uSize - trace.at) / (0.05 * uSize.y);
        confidence = clamp(min(edge.x, edge.y), 0.0, 1.0) * clamp(1.0 - r.z / 0.35, 0.0, 1.0);
        seen = texelFetch(uImage, ivec2(trace.at), 0).rgb;
        // The point met, on the ray: perspective-correct along the screen segment.
        vec3 met = mix(p * s0.z, q * s1.z, trace.t) / mix(s0.z, s1.z, trace.t);
        pathLength = min(eyeDistance + length(met - p), uFarPath);
    }
    fragColor = storableRadiance(vec4(mix(uBackground, seen, confidence), pathLength));
}
