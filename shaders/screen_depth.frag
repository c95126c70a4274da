// Level 0 of the depth pyramid screen-space mirrors trace against: view depth, in front of the camera.
in float vDepth;

out vec4 fragColor;

void main() { fragColor = vec4(vDepth, 0.0, 0.0, 1.0); }
