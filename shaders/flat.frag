// A flat colour: mirror masks (colour writes off) and resetting a mirror's pixels to the background.
#include "radiance.glsl"

uniform vec4 uFlatColor;

out vec4 fragColor;

void main() { fragColor = storableRadiance(uFlatColor); }
