// The camera's view depth for screen-space mirrors (passes::runScreenDepth): each surface the image shows,
// at its distance along the view axis.
layout(location = 0) in vec3 aPosition;

uniform mat4 uModelClip; // object → the camera's clip space
uniform mat4 uModelView; // object → the camera's view space (camera-relative, looking down −z)

out float vDepth;

void main() {
    vDepth = -(uModelView * vec4(aPosition, 1.0)).z;
    gl_Position = uModelClip * vec4(aPosition, 1.0);
}
