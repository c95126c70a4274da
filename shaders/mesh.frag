#include "lighting.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

uniform vec3 uColor;
uniform float uAmbient;
uniform float uDiffuse;
uniform float uSpecular;
uniform float uShininess;
uniform vec3 uEmission;
uniform int uHasTexture;
uniform sampler2D uTexture; // sRGB texture: sampling returns linear values
uniform float uSceneAmbient;

out vec4 fragColor;

void main() {
    vec3 normal = normalize(vNormal);
    // Two-sided: the inside of the teapot's lid gap and the underside of planes are lit as surfaces too.
    if (!gl_FrontFacing)
        normal = -normal;
    vec3 viewDir = normalize(-vWorld); // the camera sits at the origin
    vec3 base = uColor;
    if (uHasTexture != 0)
        base *= texture(uTexture, vUv).rgb;
    SurfaceLight light = shadeLights(vWorld, normal, viewDir, uShininess);
    vec3 color = uEmission + base * (uAmbient * uSceneAmbient + uDiffuse * light.diffuse) + uSpecular * light.specular;
    fragColor = vec4(color, 1.0);
}
