// One guide line (passes::GuidesPass) as a quad around it on screen, six vertices an instance: the line's
// ends and style come per instance. Its width is in pixels whatever its distance, as a guide's should be.
layout(location = 0) in vec3 aFrom; // relative to the eye
layout(location = 1) in vec3 aTo;
layout(location = 2) in vec4 aColor; // linear, straight alpha
layout(location = 3) in vec2 aStyle; // width in pixels, opacity where hidden

uniform mat4 uViewProjection; // camera-relative world → clip
uniform vec2 uViewportSize;
uniform float uNearW; // the smallest clip w kept: just beyond the near plane

out vec4 vColor;
out float vHiddenOpacity;
out float vHalfWidth;
noperspective out float vAcross; // from the line's middle, in pixels

// A line lying on a surface (the grid on a floor) has that surface's depth to the last bit: pulled this
// fraction of its distance toward the eye, it stays in front of it and still goes behind anything standing
// on it.
const float kDepthPull = 1.5e-3;

const float kEnd[6] = float[6](0.0, 1.0, 1.0, 0.0, 1.0, 0.0);
const float kSide[6] = float[6](-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);

void main() {
    vec4 a = uViewProjection * vec4(aFrom * (1.0 - kDepthPull), 1.0);
    vec4 b = uViewProjection * vec4(aTo * (1.0 - kDepthPull), 1.0);
    vColor = aColor;
    vHiddenOpacity = aStyle.y;
    // Cut where the line passes behind the eye: what is left is drawn up to where it leaves the view, not
    // flipped through the eye.
    float da = a.w - uNearW, db = b.w - uNearW;
    if (da < 0.0 && db < 0.0) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0); // outside the clip volume: nothing drawn
        vHalfWidth = 0.0;
        vAcross = 0.0;
        return;
    }
    if (da < 0.0)
        a = mix(a, b, da / (da - db));
    else if (db < 0.0)
        b = mix(b, a, db / (db - da));
    vec2 halfSize = 0.5 * uViewportSize;
    vec2 sa = a.xy / a.w * halfSize, sb = b.xy / b.w * halfSize;
    vec2 along = sb - sa;
    float length2 = dot(along, along);
    vec2 dir = length2 > 1e-12 ? along * inversesqrt(length2) : vec2(1.0, 0.0);
    vec2 normal = vec2(-dir.y, dir.x);
    // Thinner than a pixel (a preview drawn smaller): one pixel wide, fainter.
    float width = max(aStyle.x, 1.0);
    vColor.a *= min(aStyle.x, 1.0);
    vHalfWidth = 0.5 * width;
    float reach = vHalfWidth + 1.0; // one more pixel for the anti-aliased edge
    int corner = gl_VertexID % 6;
    vec4 p = kEnd[corner] > 0.5 ? b : a;
    p.xy += normal * (kSide[corner] * reach) / halfSize * p.w;
    vAcross = kSide[corner] * reach;
    gl_Position = p;
}
