// A flat colour: mirror masks (colour writes off) and resetting a mirror's pixels to the background.
uniform vec4 uFlatColor;

out vec4 fragColor;

void main() { fragColor = uFlatColor; }
