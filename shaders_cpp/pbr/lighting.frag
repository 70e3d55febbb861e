#version 330 core
// PBR, lighting pass (seed 004): a fullscreen triangle that reconstructs each pixel's world
// position from the G-buffer depth (ReconstructPosition), Cook-Torrance with the seed's GGX
// distribution, Smith geometry and Schlick Fresnel for a sun (shadowed by three cascaded
// shadow maps, each read with the seed's 5x5 ShadowPCF, the cascade chosen per pixel by
// GetCascadeIndex) and three point lights, ambient times the blurred SSAO and the material's
// AO, then the seed's exposure, ACES filmic tone map and gamma.
const float PI = 3.14159265359;
const int NUM_CASCADES = 3;
const int NUM_POINT_LIGHTS = 3;
uniform sampler2D gAlbedo;
uniform sampler2D gNormal;
uniform sampler2D gMRA;
uniform sampler2D gEmissive;
uniform sampler2D gDepth;
uniform sampler2D uSSAO;
uniform sampler2DShadow uShadowMap0;
uniform sampler2DShadow uShadowMap1;
uniform sampler2DShadow uShadowMap2;
uniform mat4 uLightVP[NUM_CASCADES];
uniform float cascadeSplits[NUM_CASCADES - 1];
uniform mat4 uInvViewProj;
uniform mat4 uView;
uniform vec3 uCamPos;
uniform vec3 uSunDir;   // unit, toward the sun
uniform vec3 uSunColor;
uniform vec3 uPointPos[NUM_POINT_LIGHTS];
uniform vec3 uPointColor[NUM_POINT_LIGHTS];
uniform float uRoughnessFloor;
uniform float uExposure;
in vec2 fragUV;
layout(location = 0) out vec4 fragColor;

vec3 ReconstructPosition(float depth, vec2 uv, mat4 invVP) {
    vec4 clip = vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec4 world = invVP * clip;
    return world.xyz / world.w;
}

float ShadowPCF(sampler2DShadow shadowMap, vec4 lightSpacePos, float bias) {
    vec3 projCoords = lightSpacePos.xyz / lightSpacePos.w;
    projCoords = projCoords * 0.5 + 0.5;
    float shadow = 0.0;
    vec2 texelSize = 1.0 / vec2(textureSize(shadowMap, 0));
    for (int x = -2; x <= 2; ++x) {
        for (int y = -2; y <= 2; ++y) {
            vec3 coord = vec3(
                projCoords.xy + vec2(x, y) * texelSize,
                projCoords.z - bias
            );
            shadow += texture(shadowMap, coord); // hw comparison
        }
    }
    return shadow / 25.0;
}

int GetCascadeIndex(float viewDepth) {
    for (int i = 0; i < NUM_CASCADES - 1; ++i) {
        if (viewDepth < cascadeSplits[i])
            return i;
    }
    return NUM_CASCADES - 1;
}

// GGX Normal Distribution Function
float D_GGX(float NdotH, float roughness) {
    float a = roughness * roughness;
    float a2 = a * a;
    float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

// Smith Geometry function (combined masking + shadowing)
float G_Smith(float NdotV, float NdotL, float roughness) {
    float r = roughness + 1.0;
    float k = (r * r) / 8.0; // direct lighting remapping
    float gv = NdotV / (NdotV * (1.0 - k) + k);
    float gl = NdotL / (NdotL * (1.0 - k) + k);
    return gv * gl;
}

// Fresnel-Schlick
vec3 F_Schlick(float cosTheta, vec3 F0) {
    return F0 + (1.0 - F0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

// Full Cook-Torrance specular term
vec3 CookTorranceSpecular(vec3 N, vec3 V, vec3 L, vec3 F0, float roughness) {
    vec3 H = normalize(V + L);
    float NdotH = max(dot(N, H), 0.0);
    float NdotV = max(dot(N, V), 0.0);
    float NdotL = max(dot(N, L), 0.0);
    float D = D_GGX(NdotH, roughness);
    float G = G_Smith(NdotV, NdotL, roughness);
    vec3 F = F_Schlick(max(dot(H, V), 0.0), F0);
    return (D * G * F) / (4.0 * NdotV * NdotL + 0.0001);
}

// ACES filmic tone map approximation (Narkowicz 2015)
vec3 ACESFilmic(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a*x + b)) / (x * (c*x + d) + e), 0.0, 1.0);
}

// One light's reflected radiance: the diffuse share the Fresnel term leaves (kD, none for a
// metal) plus the Cook-Torrance specular, times the light's radiance and N.L.
vec3 DirectLight(vec3 N, vec3 V, vec3 L, vec3 radiance, vec3 albedo, float metallic, float roughness, vec3 F0) {
    vec3 kD = (1.0 - F_Schlick(max(dot(normalize(V + L), V), 0.0), F0)) * (1.0 - metallic);
    vec3 specular = CookTorranceSpecular(N, V, L, F0, roughness);
    float NdotL = max(dot(N, L), 0.0);
    vec3 brdf = kD * albedo / PI + specular;
    vec3 lit = radiance * NdotL;
    return brdf * lit;
}

float CascadeShadow(int cascade, vec3 P, float bias) {
    if (cascade == 0)
        return ShadowPCF(uShadowMap0, uLightVP[0] * vec4(P, 1.0), bias);
    if (cascade == 1)
        return ShadowPCF(uShadowMap1, uLightVP[1] * vec4(P, 1.0), bias);
    return ShadowPCF(uShadowMap2, uLightVP[2] * vec4(P, 1.0), bias);
}

void main() {
    vec2 uv = fragUV;
    vec3 color = mix(vec3(0.30, 0.36, 0.46), vec3(0.62, 0.70, 0.82), uv.y);   // the sky
    if (texture(gEmissive, uv).a > 0.5) {
        float depth = texture(gDepth, uv).r;
        vec3 P = ReconstructPosition(depth, uv, uInvViewProj);
        vec3 N = normalize(texture(gNormal, uv).rgb * 2.0 - 1.0);
        vec3 albedo = pow(texture(gAlbedo, uv).rgb, vec3(2.2));   // sRGB texels -> linear
        vec3 mra = texture(gMRA, uv).rgb;
        float metallic = mra.r;
        float roughness = max(mra.g, uRoughnessFloor);
        float ao = mra.b * texture(uSSAO, uv).r;
        vec3 emissive = texture(gEmissive, uv).rgb;
        vec3 V = normalize(uCamPos - P);
        vec3 F0 = mix(vec3(0.04), albedo, metallic);

        float viewDepth = -(uView * vec4(P, 1.0)).z;
        int cascade = GetCascadeIndex(viewDepth);
        float NdotSun = max(dot(N, uSunDir), 0.0);
        float bias = max(0.0015 * (1.0 - NdotSun), 0.0004);
        float shadow = CascadeShadow(cascade, P, bias);

        vec3 Lo = DirectLight(N, V, uSunDir, uSunColor * shadow, albedo, metallic, roughness, F0);
        for (int i = 0; i < NUM_POINT_LIGHTS; ++i) {
            vec3 toLight = uPointPos[i] - P;
            float dist = length(toLight);
            vec3 L = toLight / dist;
            Lo += DirectLight(N, V, L, uPointColor[i] / (dist * dist), albedo, metallic, roughness, F0);
        }
        vec3 ambient = vec3(0.03) * albedo * ao;
        color = ambient + Lo + emissive;
    }
    vec3 hdrColor = color;
    // Exposure adjustment before tone mapping
    hdrColor *= uExposure;
    vec3 ldr = ACESFilmic(hdrColor);
    // Gamma correction (linear -> sRGB)
    ldr = pow(ldr, vec3(1.0 / 2.2));
    fragColor = vec4(ldr, 1.0);
}
