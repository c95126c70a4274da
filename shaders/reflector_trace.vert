// The curved reflector, drawn again over itself for its screen-space trace (shaders/reflector_trace.frag):
// its points and normals in the camera's view space.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModelClip;  // object → the camera's clip space
uniform mat4 uModelView;  // object → the camera's view space
uniform mat3 uNormalView; // object normals → view space (the inverse transpose)

out vec3 vView;
out vec3 vNormalView;

void main() {
    vView = (uModelView * vec4(aPosition, 1.0)).xyz;
    vNormalView = uNormalView * aNormal;
    gl_Position = uModelClip * vec4(aPosition, 1.0);
}
