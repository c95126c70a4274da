layout(location = 0) in vec3 aPosition;

uniform mat4 uModelLightClip; // object → light clip space

void main() { gl_Position = uModelLightClip * vec4(aPosition, 1.0); }
