// A guide line's pixels: its colour, faded over the last pixel of its edges, and only its see-through
// opacity in the pass that draws where the scene hides it.
in vec4 vColor;
in float vHiddenOpacity;
in float vHalfWidth;
noperspective in float vAcross;

uniform int uHiddenPass;

out vec4 fragColor;

void main() {
    float coverage = clamp(vHalfWidth + 0.5 - abs(vAcross), 0.0, 1.0);
    float alpha = vColor.a * coverage * (uHiddenPass != 0 ? vHiddenOpacity : 1.0);
    if (alpha <= 0.0)
        discard;
    fragColor = vec4(vColor.rgb, alpha);
}
