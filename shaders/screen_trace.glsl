// Screen-space reflections (the screen-space mirrors, shaders/screen_trace.frag, and the curved reflector's
// trace, shaders/reflector_trace.frag): a reflected ray followed across the camera's own image through the
// depth pyramid of minima (shaders/depth_min.frag), hierarchical-Z: where the ray, over a cell of some
// level, stays nearer than everything in it, it skips the cell and climbs a level; otherwise it descends,
// down to single pixels, where it meets the surface the image shows if it has gone behind it by less than
// the thickness. Where it leaves the image, comes back towards the camera, passes behind everything it
// crosses or runs out of steps, the image holds nothing it sees: the fallback shows, the curved
// reflector's environment map looked up as a probe from the point (through its parallax proxy when it has
// one) or the background. The fallback fades in by the trace's confidence, towards the image's edges, as
// the ray turns towards the camera and as it passes further behind what it met, so that no seam marks the
// change.
#include "radiance.glsl"
#include "reflector_lookup.glsl"

uniform sampler2D uDepthPyramid; // view depth, each level the minimum of the one below (R32F)
uniform sampler2D uImage;        // the camera's linear colour, as every other pass left it; for a cone
                                 // trace, with its pyramid of blurred levels (uImageLevels of them)
uniform int uImageLevels;
uniform int uLevels;
uniform vec2 uSize;       // the image's pixels
uniform mat4 uProjection; // view → clip
uniform float uNear;
uniform int uSteps;
uniform float uThickness; // a share of the surface's view depth
uniform vec3 uBackground;
uniform float uFarPath; // the path length of the background (material.glsl's alpha for nothing hit)
// The fallback: 0 the background, 1 the reflector's map (ReflectorPass::bindAsProbe sets the rest).
uniform int uFallback;
uniform mat3 uWorldFromView; // view space → camera-relative world space (a rotation)
// 0: the reflection's radiance and path length; 1: where it came from, in colour (the debug view, and
// the counts a still reports): green, met in the image; blue, the map; red, the background.
uniform int uShowSources;


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
    float t;      // along the screen segment
    vec2 at;      // pixels
    float behind; // how far behind the surface met the ray passes there, a share of the thickness (≤ 1)
};

Trace traceImage(vec3 s0, vec3 s1, float tEnd) {
    vec2 d = s1.xy - s0.xy;
    float perPixel = 1.0 / max(length(d), 1e-6);
    Trace result = Trace(false, 0.0, s0.xy, 0.0);
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
            result = Trace(true, t, at, (min(depthIn, depthOut) - surface) / (surface * uThickness));
            break;
        } else { // behind the surface by more than its thickness: the ray passes behind it
            t = tExit + 0.02 * perPixel;
        }
    }
    return result;
}

// What the fallback shows along the ray r from the point p (view space): rgb, and the path
// length from the eye (the background's where the map has no proxy to say how far).
vec4 fallback(vec3 p, vec3 r, float eyeDistance) {
    if (uFallback == 0)
        return vec4(uBackground, uFarPath);
    vec3 worldRay = uWorldFromView * r;
    vec4 hit = uParallax != 0 ? parallaxHit(uWorldFromView * p - uEnvCentre, worldRay) : vec4(worldRay, 0.0);
    vec3 d = normalize(hit.xyz);
    vec3 dx = dFdx(d);
    vec3 dy = dFdy(d);
    vec3 seen = uEnvType == ENVMAP_CUBE ? envmapLookupCube(uEnvCube, d, dx, dy).rgb
                                        : envmapLookup2D(uEnvArray, uEnvType, uEnvLayout, d, dx, dy).rgb;
    return vec4(seen, hit.w > 0.0 ? min(eyeDistance + hit.w, uFarPath) : uFarPath);
}

// A reflected ray traced through the image: what it shows, the fallback blended in by the confidence.
struct Reflection {
    vec3 colour;      // the image where the ray meets it, the fallback where it does not, blended
    float pathLength; // from the eye, through the point, to what it shows
    float confidence; // 1: what the image shows; 0: the fallback
    vec3 missed;      // the fallback alone
};

// What the image shows where a ray met it, at `at` (pixels): the pixel itself for a sharp ray; for a cone
// `spread` wide per unit of path (radians), the level of the blurred pyramid whose texels are as wide as
// the cone is where it meets the image, `along` from its start and `depth` from the eye — how the image's
// pyramid stands in for the glossy lobe, as Godot's and HDRP's rough screen-space reflections do.
vec3 imageSeen(vec2 at, float spread, float along, float depth) {
    if (spread <= 0.0)
        return texelFetch(uImage, ivec2(at), 0).rgb;
    float pixelsPerUnit = uProjection[1][1] * 0.5 * uSize.y / max(depth, uNear);
    float lod = log2(max(spread * along * pixelsPerUnit, 1.0));
    return textureLod(uImage, at / uSize, clamp(lod, 0.0, float(uImageLevels - 1))).rgb;
}

// The ray r (unit, view space) from the point p, which the eye sees eyeDistance away; the trace starts at
// `origin` (p, or a little off a surface the image itself shows, so that the ray does not meet it).
// `missed`: what shows where the image holds nothing (fallback(), or what the reflector's surface drew),
// and its path length; `spread`: the cone's width per unit of path, 0 for one sharp ray.
Reflection traceReflection(vec3 p, vec3 origin, vec3 r, float eyeDistance, vec4 missed, float spread) {
    // Far enough to leave the view; coming back towards the camera, only to just before its near plane.
    float reach = 1e4 * max(eyeDistance, 1.0);
    if (r.z > 1e-6)
        reach = min(reach, 0.99 * (-uNear - origin.z) / r.z);
    vec3 q = origin + r * max(reach, 0.0);
    vec3 s0 = toScreen(origin);
    vec3 s1 = toScreen(q);
    vec2 d = s1.xy - s0.xy;
    float tEnd = min(1.0, min(leaves(s0.x, d.x, uSize.x), leaves(s0.y, d.y, uSize.y)));
    Trace trace = Trace(false, 0.0, s0.xy, 0.0);
    if (reach > 0.0 && length(d) * tEnd >= 1.0 && s0.z > 0.0)
        trace = traceImage(s0, s1, tEnd);
    Reflection result = Reflection(missed.rgb, missed.a, 0.0, missed.rgb);
    if (trace.hit) {
        vec2 edge = min(trace.at, uSize - trace.at) / (0.05 * uSize.y);
        // Less sure towards the image's edges, as the ray turns towards the camera (it meets the backs of
        // things, which the image does not show), and where it passes behind what it met by more than half
        // the thickness (it may be passing behind a thin object rather than meeting it).
        result.confidence = clamp(min(edge.x, edge.y), 0.0, 1.0) * clamp(1.0 - r.z / 0.35, 0.0, 1.0) *
                            clamp(2.0 - 2.0 * trace.behind, 0.0, 1.0);
        // The point met, on the ray: perspective-correct along the screen segment.
        vec3 met = mix(origin * s0.z, q * s1.z, trace.t) / mix(s0.z, s1.z, trace.t);
        vec3 seen = imageSeen(trace.at, spread, length(met - origin), -met.z);
        result.colour = mix(missed.rgb, seen, result.confidence);
        if (result.confidence > 0.0)
            result.pathLength = min(eyeDistance + length(met - p), uFarPath);
    }
    return result;
}

// Where a reflection came from, in colour (uShowSources): green, the image; blue, the map; red, the
// background; blended by the confidence.
vec3 sourceColour(float confidence) {
    vec3 source = uFallback != 0 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    return mix(source, vec3(0.0, 1.0, 0.0), confidence);
}
