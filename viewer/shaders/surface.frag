#version 330 core
// X3D lighting (19775-1 17.2.2.4), per fragment: emissive + for each light
// ambient + diffuse + specular (Blinn), the diffuse colour per vertex; the
// headlight is a directional light from the eye. Unlit shapes, and points
// without a normal (inside a solid), show their colour as it is. A clip plane
// cuts everything on its negative side.
in vec3 worldPosition;
in vec3 worldNormal;
in vec4 colour;
in vec2 texCoord;

out vec4 fragColor;

uniform vec3 eyePosition;

uniform int lit;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float ambientIntensity;
uniform int twoSided;

// 0: no texture; 1: an intensity image scales the colour; 3: a colour image
// replaces it. Its alpha multiplies the colour's (transparency) either way.
uniform int textured;
uniform sampler2D diffuseTexture;

const int kMaxLights = 8;
uniform int headlight;
uniform int lightCount;
uniform vec4 lightPosition[kMaxLights];    // w = 0: a direction the light travels; 1: a point
uniform vec4 lightColour[kMaxLights];      // rgb: colour * intensity; a: ambientIntensity
uniform vec4 lightAttenuation[kMaxLights]; // xyz: constant, linear, quadratic; w: radius
uniform vec4 lightSpot[kMaxLights];        // xyz: direction; w: cos(cutOffAngle), -2 if none

uniform int clipOn;
uniform vec4 clipPlane;

vec3 shade(vec3 base, vec3 n, vec3 v, vec3 toLight, vec3 intensity, float ambient)
{
    vec3 c = ambient * ambientIntensity * base;
    float d = max(dot(n, toLight), 0.0);
    c += intensity * base * d;
    if (d > 0.0) {
        vec3 h = normalize(toLight + v);
        c += intensity * specular * pow(max(dot(n, h), 0.0), max(shininess * 128.0, 1.0));
    }
    return c;
}

void main()
{
    if (clipOn == 1 && dot(vec4(worldPosition, 1.0), clipPlane) < 0.0)
        discard;
    vec3 base = colour.rgb;
    float alpha = colour.a;
    if (textured != 0) {
        vec4 image = texture(diffuseTexture, texCoord);
        base = textured == 1 ? base * image.r : image.rgb;
        alpha *= image.a;
    }
    if (lit == 0 || dot(worldNormal, worldNormal) < 1e-12) {
        fragColor = vec4(base, alpha);
        return;
    }
    vec3 n = normalize(worldNormal);
    vec3 v = normalize(eyePosition - worldPosition);
    if (twoSided == 1 && dot(n, v) < 0.0)
        n = -n;
    vec3 c = emissive;
    if (headlight == 1)
        c += shade(base, n, v, v, vec3(1.0), 0.0);
    for (int i = 0; i < lightCount && i < kMaxLights; ++i) {
        vec3 toLight;
        float fade = 1.0;
        if (lightPosition[i].w == 0.0) {
            toLight = normalize(-lightPosition[i].xyz);
        } else {
            vec3 d = lightPosition[i].xyz - worldPosition;
            float dist = length(d);
            if (dist > lightAttenuation[i].w)
                continue;
            toLight = d / max(dist, 1e-9);
            vec3 a = lightAttenuation[i].xyz;
            fade = 1.0 / max(a.x + a.y * dist + a.z * dist * dist, 1.0);
            if (lightSpot[i].w > -1.5 && dot(-toLight, normalize(lightSpot[i].xyz)) < lightSpot[i].w)
                continue;
        }
        c += fade * shade(base, n, v, toLight, lightColour[i].rgb, lightColour[i].a);
    }
    fragColor = vec4(min(c, vec3(1.0)), alpha);
}
