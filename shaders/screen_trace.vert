// A screen-space mirror's rectangle, drawn as the camera sees it into the mirror's reflection texture
// (shaders/screen_trace.frag traces each of its pixels).
layout(location = 0) in vec3 aPosition;

uniform mat4 uModelClip; // object → the camera's clip space
uniform mat4 uModelView; // object → the camera's view space

out vec3 vView;

void main() {
    vView = (uModelView * vec4(aPosition, 1.0)).xyz;
    gl_Position = uModelClip * vec4(aPosition, 1.0);
}
