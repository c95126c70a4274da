// The parallax proxy of the curved reflector's map (ParallaxParams): the shape of the surroundings the map
// is taken to show, so that a lookup from a point away from the capture point finds the texel that shows
// what its ray meets. The reflector's surface (reflector.frag) and the screen-space fallback
// (screen_trace.frag) read it.
#ifndef PARALLAX_GLSL
#define PARALLAX_GLSL

uniform int uParallax;          // 0 off, 1 sphere, 2 box
uniform float uParallaxRadius;
uniform vec3 uParallaxMin;      // relative to the capture point
uniform vec3 uParallaxMax;

// Parallax correction: the point where the reflected ray from the shaded point p leaves the proxy, seen
// from the capture point (xyz), and how far along the ray that is (w). A ray that never meets the proxy
// (the point outside it) keeps its direction, and w is 0.
vec4 parallaxHit(vec3 p, vec3 r) {
    if (uParallax == 1) {
        float b = dot(p, r);
        float c = dot(p, p) - uParallaxRadius * uParallaxRadius;
        float disc = b * b - c;
        float t = -b + sqrt(max(disc, 0.0));
        return (disc >= 0.0 && t > 0.0) ? vec4(p + t * r, t) : vec4(r, 0.0);
    }
    vec3 safe = mix(vec3(1e-20), r, greaterThan(abs(r), vec3(1e-20)));
    vec3 t1 = (uParallaxMin - p) / safe;
    vec3 t2 = (uParallaxMax - p) / safe;
    vec3 tFar = max(t1, t2);
    float t = min(tFar.x, min(tFar.y, tFar.z));
    return t > 0.0 ? vec4(p + t * r, t) : vec4(r, 0.0);
}

#endif
