// Environment-map mappings and seamless lookups for pass 2 (the reflector). The GLSL twin of
// render/envmap/Mapping.cpp and Layout.hpp: read those for the conventions. Component indices are 0-based
// (0 is the reference's "component 1"); uv are nominal, in [0,1]² inside a component.
//
// Binding: a cube map is a samplerCube (with GL_TEXTURE_CUBE_MAP_SEAMLESS on); the two components of a
// dual-paraboloid or tennis-ball map are the two layers of one sampler2DArray (an octahedral map its one
// layer), and `mapLayout` is
// MapLayout::packed() (mapLayout): (scale.xy, offset.xy) from nominal uv to texture coordinates, past a guard band.
#ifndef ENVMAP_LOOKUP_GLSL
#define ENVMAP_LOOKUP_GLSL

#define ENVMAP_CUBE 0
#define ENVMAP_DUAL_PARABOLOID 1
#define ENVMAP_TENNIS_BALL 2
#define ENVMAP_OCTAHEDRAL 3

const float kEnvQuarterPi = 0.78539816339744831;
const float kEnvThreeQuarterPi = 2.35619449019234492;
const float kEnvHalfSqrt2 = 0.70710678118654752;

// atan(y, x) is undefined where both vanish (a tennis-ball pole, never looked up in that component).
float envmapAtan2(float y, float x) {
    return (x == 0.0 && y == 0.0) ? 0.0 : atan(y, x);
}

// asin with its argument clamped, computed through atan: some drivers' asin (Mesa's, for one) is only
// good to about 1e-4 rad, which would misplace lookups by a tenth of a texel at n = 512.
float envmapAsin(float s) {
    s = clamp(s, -1.0, 1.0);
    return atan(s, sqrt(max(1.0 - s * s, 0.0)));
}

// --- cube (GL face order +X −X +Y −Y +Z −Z; (sc, tc) as in the GL spec, §8.13) ---
int envmapCubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z)
        return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

void envmapCubeFrame(int face, out vec3 m, out vec3 s, out vec3 t) {
    if (face == 0) { m = vec3(1, 0, 0); s = vec3(0, 0, -1); t = vec3(0, -1, 0); }
    else if (face == 1) { m = vec3(-1, 0, 0); s = vec3(0, 0, 1); t = vec3(0, -1, 0); }
    else if (face == 2) { m = vec3(0, 1, 0); s = vec3(1, 0, 0); t = vec3(0, 0, 1); }
    else if (face == 3) { m = vec3(0, -1, 0); s = vec3(1, 0, 0); t = vec3(0, 0, -1); }
    else if (face == 4) { m = vec3(0, 0, 1); s = vec3(1, 0, 0); t = vec3(0, -1, 0); }
    else { m = vec3(0, 0, -1); s = vec3(-1, 0, 0); t = vec3(0, -1, 0); }
}

vec2 envmapCubeUv(int face, vec3 d) {
    vec3 m, s, t;
    envmapCubeFrame(face, m, s, t);
    return vec2(dot(d, s), dot(d, t)) / dot(d, m) * 0.5 + 0.5;
}

vec3 envmapCubeDirection(int face, vec2 uv) {
    vec3 m, s, t;
    envmapCubeFrame(face, m, s, t);
    vec2 st = uv * 2.0 - 1.0;
    return normalize(m + st.x * s + st.y * t);
}

// --- dual paraboloid: component 0 for z < 0 (d = 1 − z), component 1 for z ≥ 0 (d = 1 + z) ---
int envmapParaboloidComponent(vec3 d) {
    return d.z < 0.0 ? 0 : 1;
}

vec2 envmapParaboloidUv(int component, vec3 d) {
    float denom = component == 0 ? 1.0 - d.z : 1.0 + d.z; // ≥ 1 in the chosen component
    return d.xy / denom * 0.5 + 0.5;
}

vec3 envmapParaboloidDirection(int component, vec2 uv) {
    vec2 p = uv * 2.0 - 1.0;
    float r2 = dot(p, p);
    float z = (1.0 - r2) / (1.0 + r2);
    return vec3(2.0 * p / (1.0 + r2), component == 0 ? -z : z);
}

// --- tennis ball: u holds a = asin(·)/(π/4) (n texels), v holds b = atan(·)/(3π/4) (3n texels) ---
int envmapTennisBallComponent(vec3 d) {
    return ((d.z >= 0.0 && abs(d.y) <= kEnvHalfSqrt2) || (d.z <= 0.0 && abs(d.x) >= kEnvHalfSqrt2)) ? 0 : 1;
}

vec2 envmapTennisBallUv(int component, vec3 d) {
    float a = envmapAsin(component == 0 ? d.y : d.x) / kEnvQuarterPi;
    float b = (component == 0 ? envmapAtan2(d.x, d.z) : envmapAtan2(d.y, -d.z)) / kEnvThreeQuarterPi;
    return vec2(a, b) * 0.5 + 0.5;
}

vec3 envmapTennisBallDirection(int component, vec2 uv) {
    float latitude = (uv.x * 2.0 - 1.0) * kEnvQuarterPi;
    float longitude = (uv.y * 2.0 - 1.0) * kEnvThreeQuarterPi;
    float c = cos(latitude);
    float s = sin(latitude);
    if (component == 0)
        return vec3(c * sin(longitude), s, c * cos(longitude));
    return vec3(s, c * sin(longitude), -c * cos(longitude));
}

// --- octahedral: one component; the lower half (z < 0) folded out into the square's corners ---
vec2 envmapFoldSign(vec2 v) {
    return vec2(v.x < 0.0 ? -1.0 : 1.0, v.y < 0.0 ? -1.0 : 1.0);
}

vec2 envmapOctahedralUv(vec3 d) {
    vec2 p = d.xy / (abs(d.x) + abs(d.y) + abs(d.z));
    if (d.z < 0.0)
        p = envmapFoldSign(p) * (1.0 - abs(p.yx));
    return p * 0.5 + 0.5;
}

vec3 envmapOctahedralDirection(vec2 uv) {
    vec2 p = uv * 2.0 - 1.0;
    // Past a side the square continues folded over it: (1 + e, t) is (1 − e, −t) (the guard band).
    for (int i = 0; i < 4 && (abs(p.x) > 1.0 || abs(p.y) > 1.0); ++i) {
        if (abs(p.x) > 1.0)
            p = vec2(envmapFoldSign(p).x * 2.0 - p.x, -p.y);
        if (abs(p.y) > 1.0)
            p = vec2(-p.x, envmapFoldSign(p).y * 2.0 - p.y);
    }
    p = clamp(p, -1.0, 1.0);
    float z = 1.0 - abs(p.x) - abs(p.y);
    if (z < 0.0)
        p = envmapFoldSign(p) * (1.0 - abs(p.yx));
    return normalize(vec3(p, z));
}

// --- any map (type: ENVMAP_*); d need not be unit length ---
int envmapComponent(int type, vec3 d) {
    d = normalize(d);
    if (type == ENVMAP_CUBE)
        return envmapCubeFace(d);
    if (type == ENVMAP_DUAL_PARABOLOID)
        return envmapParaboloidComponent(d);
    if (type == ENVMAP_OCTAHEDRAL)
        return 0;
    return envmapTennisBallComponent(d);
}

vec2 envmapUv(int type, int component, vec3 d) {
    d = normalize(d);
    if (type == ENVMAP_CUBE)
        return envmapCubeUv(component, d);
    if (type == ENVMAP_DUAL_PARABOLOID)
        return envmapParaboloidUv(component, d);
    if (type == ENVMAP_OCTAHEDRAL)
        return envmapOctahedralUv(d);
    return envmapTennisBallUv(component, d);
}

vec3 envmapDirection(int type, int component, vec2 uv) {
    if (type == ENVMAP_CUBE)
        return envmapCubeDirection(component, uv);
    if (type == ENVMAP_DUAL_PARABOLOID)
        return envmapParaboloidDirection(component, uv);
    if (type == ENVMAP_OCTAHEDRAL)
        return envmapOctahedralDirection(uv);
    return envmapTennisBallDirection(component, uv);
}

// ∂uv/∂d at a unit direction (columns: ∂uv/∂x, ∂uv/∂y, ∂uv/∂z), for the non-linear maps.
mat3x2 envmapUvJacobian(int type, int component, vec3 d) {
    vec3 du, dv;
    if (type == ENVMAP_DUAL_PARABOLOID) {
        float sign = component == 0 ? 1.0 : -1.0;
        float denom = 1.0 - sign * d.z;
        du = 0.5 * vec3(1.0 / denom, 0.0, sign * d.x / (denom * denom));
        dv = 0.5 * vec3(0.0, 1.0 / denom, sign * d.y / (denom * denom));
    } else if (type == ENVMAP_OCTAHEDRAL) {
        float s = abs(d.x) + abs(d.y) + abs(d.z);
        vec3 signs = vec3(envmapFoldSign(d.xy), d.z < 0.0 ? -1.0 : 1.0);
        vec3 dpx = (vec3(1.0, 0.0, 0.0) - (d.x / s) * signs) / s;
        vec3 dpy = (vec3(0.0, 1.0, 0.0) - (d.y / s) * signs) / s;
        du = 0.5 * dpx;
        dv = 0.5 * dpy;
        if (d.z < 0.0) { // folded: u = ½ sign(p.x)(1 − |p.y|) + ½, v = ½ sign(p.y)(1 − |p.x|) + ½
            float flip = -signs.x * signs.y;
            du = 0.5 * flip * dpy;
            dv = 0.5 * flip * dpx;
        }
    } else if (component == 0) {
        float ring = max(d.x * d.x + d.z * d.z, 1e-12); // ≥ ½ where component 0 is looked up
        du = vec3(0.0, 0.5 / (sqrt(ring) * kEnvQuarterPi), 0.0);
        dv = vec3(d.z, 0.0, -d.x) * (0.5 / (ring * kEnvThreeQuarterPi));
    } else {
        float ring = max(d.y * d.y + d.z * d.z, 1e-12);
        du = vec3(0.5 / (sqrt(ring) * kEnvQuarterPi), 0.0, 0.0);
        dv = vec3(0.0, -d.z, d.y) * (0.5 / (ring * kEnvThreeQuarterPi));
    }
    return mat3x2(du.x, dv.x, du.y, dv.y, du.z, dv.z);
}

// The reflection vector R = 2(N·E)N − E, kept in the outside hemisphere: where an interpolated normal
// turns away from the eye (silhouettes), N·E is taken as 0, the grazing limit R = −E, continuously.
// E: unit vector from the surface to the eye; N: unit normal.
vec3 envmapReflection(vec3 E, vec3 N) {
    return 2.0 * max(dot(N, E), 0.0) * N - E;
}

// Cube lookup. dDdx, dDdy: screen derivatives of the unit direction (dFdx/dFdy of normalize(R)), which
// are continuous; GL's seamless cube filtering handles the faces.
vec4 envmapLookupCube(samplerCube map, vec3 d, vec3 dDdx, vec3 dDdy) {
    return textureGrad(map, d, dDdx, dDdy);
}

// Dual-paraboloid or tennis-ball lookup. The component is chosen per fragment; the uv gradients come from
// the continuous direction gradients through the chosen component's Jacobian, so the LOD does not jump
// where neighbouring fragments use different components (implicit derivatives of uv would), and the
// guard band makes bilinear/trilinear filtering near a component's edge read real environment.
vec4 envmapLookup2D(sampler2DArray map, int type, vec4 mapLayout, vec3 d, vec3 dDdx, vec3 dDdy) {
    d = normalize(d);
    int component = envmapComponent(type, d);
    vec2 uv = mapLayout.zw + mapLayout.xy * envmapUv(type, component, d);
    mat3x2 j = envmapUvJacobian(type, component, d);
    vec2 gx = mapLayout.xy * (j * dDdx);
    vec2 gy = mapLayout.xy * (j * dDdy);
    return textureGrad(map, vec3(uv, float(component)), gx, gy);
}

// The rough reflector's lookups: at least `lod` (the roughness's level of a pre-filtered chain or of the
// map's mip chain), and never sharper than the pixel's footprint, which the sharp lookups' gradients give:
// log2 of the footprint in texels. The cube's texels span about 2/n of a unit direction at a face's centre.
float envmapFootprintLod(vec2 texelsX, vec2 texelsY) {
    return 0.5 * log2(max(max(dot(texelsX, texelsX), dot(texelsY, texelsY)), 1e-20));
}

vec4 envmapLookupCubeLod(samplerCube map, vec3 d, vec3 dDdx, vec3 dDdy, float lod) {
    float texelsPerUnit = 0.5 * float(textureSize(map, 0).x);
    float footprint = 0.5 * log2(max(max(dot(dDdx, dDdx), dot(dDdy, dDdy)), 1e-20)) + log2(texelsPerUnit);
    return textureLod(map, d, max(lod, footprint));
}

vec4 envmapLookup2DLod(sampler2DArray map, int type, vec4 mapLayout, vec3 d, vec3 dDdx, vec3 dDdy, float lod) {
    d = normalize(d);
    int component = envmapComponent(type, d);
    vec2 uv = mapLayout.zw + mapLayout.xy * envmapUv(type, component, d);
    mat3x2 j = envmapUvJacobian(type, component, d);
    vec2 size = vec2(textureSize(map, 0).xy);
    float footprint = envmapFootprintLod(size * (mapLayout.xy * (j * dDdx)), size * (mapLayout.xy * (j * dDdy)));
    return textureLod(map, vec3(uv, float(component)), max(lod, footprint));
}

// A lookup at exactly `lod`: for a chain whose levels are not resolutions (the GGX pre-filtered chain).
vec4 envmapLookup2DAtLod(sampler2DArray map, int type, vec4 mapLayout, vec3 d, float lod) {
    d = normalize(d);
    int component = envmapComponent(type, d);
    vec2 uv = mapLayout.zw + mapLayout.xy * envmapUv(type, component, d);
    return textureLod(map, vec3(uv, float(component)), lod);
}

#endif
