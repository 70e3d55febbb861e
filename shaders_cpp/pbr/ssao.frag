#version 330 core
// PBR, SSAO pass (seed 004): the seed's 64-sample hemisphere kernel (generated on the host,
// scenes/pbr/pbr_scene.cpp), oriented per pixel by a 4x4 tiled noise texture through
// Gram-Schmidt, in view space. The seed compares a sample's view z with the depth texture's
// raw value; here the stored point is reconstructed to view space first (ReconstructViewPos),
// so both sides of the test are view-space z. The G-buffer normal is world-space: uView
// turns it to view space.
const int KERNEL_SIZE = 64;
uniform vec3 uSamples[KERNEL_SIZE];
uniform sampler2D uDepth;
uniform sampler2D uNormal;
uniform sampler2D uNoise;   // 4x4 tiled rotation vectors
uniform mat4 uProjection;
uniform mat4 uInvProjection;
uniform mat4 uView;
uniform vec2 noiseScale;
uniform float uRadius;
uniform float uBias;
in vec2 fragUV;
layout(location = 0) out vec4 fragColor;

vec3 ReconstructViewPos(vec2 uv) {
    float depth = texture(uDepth, uv).r;
    vec4 clip = vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec4 view = uInvProjection * clip;
    return view.xyz / view.w;
}

void main() {
    vec2 uv = fragUV;
    vec3 worldNormal = texture(uNormal, uv).rgb * 2.0 - 1.0;
    vec3 normal = normalize((uView * vec4(worldNormal, 0.0)).xyz);
    vec3 randVec = normalize(texture(uNoise, uv * noiseScale).rgb);
    // Gram-Schmidt: build TBN from noise + normal
    vec3 tangent = normalize(randVec - normal * dot(randVec, normal));
    vec3 bitangent = cross(normal, tangent);
    mat3 TBN = mat3(tangent, bitangent, normal);
    float occlusion = 0.0;
    vec3 fragPos = ReconstructViewPos(uv);
    for (int i = 0; i < KERNEL_SIZE; ++i) {
        vec3 samplePos = fragPos + TBN * uSamples[i] * uRadius;
        vec4 offset = uProjection * vec4(samplePos, 1.0);
        offset.xyz /= offset.w;
        offset.xy = offset.xy * 0.5 + 0.5;
        float sampleDepth = ReconstructViewPos(offset.xy).z;
        float rangeCheck = smoothstep(0.0, 1.0, uRadius / abs(fragPos.z - sampleDepth));
        occlusion += (sampleDepth >= samplePos.z + uBias ? 1.0 : 0.0) * rangeCheck;
    }
    fragColor = vec4(vec3(1.0 - occlusion / KERNEL_SIZE), 1.0);
}
