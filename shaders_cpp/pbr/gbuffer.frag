#version 330 core
// PBR, geometry pass (seed 004's G-buffer): four colour attachments after the seed's table,
// each written as a vec4 (the targets are RGBA, see scenes/pbr/pbr_scene.cpp):
//   0 albedo (sRGB texels as stored), 1 world normal encoded to [0,1],
//   2 metallic / roughness / AO, 3 emissive + a flag (alpha 1 = geometry, 0 = background).
// The material maps are real: the cat's diff / arm / nor_gl, the bricks' Color / NormalGL /
// Roughness / AmbientOcclusion, with the normal map applied through a tangent frame from
// screen-space derivatives (no per-vertex tangents in the OBJ).
layout(location = 0) out vec4 gAlbedo;
layout(location = 1) out vec4 gNormal;
layout(location = 2) out vec4 gMRA;   // metallic, roughness, AO
layout(location = 3) out vec4 gEmissive;
in vec3 fragPos;
in vec3 fragNormal;
in vec2 fragUV;
uniform float uMaterial;   // 0 = cat, 1 = floor
uniform sampler2D uAlbedoMap;
uniform sampler2D uNormalMap;
uniform sampler2D uMRAMap;   // the cat's ARM: AO (r), roughness (g), metallic (b)
uniform sampler2D uFloorAlbedoMap;
uniform sampler2D uFloorNormalMap;
uniform sampler2D uFloorRoughnessMap;
uniform sampler2D uFloorAOMap;

// Derivative-based TBN (Schueler 2010): a tangent frame from screen-space derivatives of
// world position + uv.
vec3 perturb_normal(vec3 nrm, vec3 p, vec2 uv, vec3 tn) {
    vec3 dp1 = dFdx(p);
    vec3 dp2 = dFdy(p);
    vec2 duv1 = dFdx(uv);
    vec2 duv2 = dFdy(uv);
    vec3 dp2perp = cross(dp2, nrm);
    vec3 dp1perp = cross(nrm, dp1);
    vec3 T = dp2perp * duv1.x + dp1perp * duv2.x;
    vec3 B = dp2perp * duv1.y + dp1perp * duv2.y;
    float invmax = 1.0 / sqrt(max(dot(T, T), dot(B, B)));
    return normalize(T * (tn.x * invmax) + B * (tn.y * invmax) + nrm * tn.z);
}

void main() {
    vec3 normal = normalize(fragNormal);
    vec3 albedo;
    vec3 mra;
    vec3 tn;
    vec2 uv;
    if (uMaterial > 0.5) {
        uv = fragPos.xz * 0.35;
        albedo = texture(uFloorAlbedoMap, uv).rgb;
        mra = vec3(0.0, texture(uFloorRoughnessMap, uv).r, texture(uFloorAOMap, uv).r);
        tn = texture(uFloorNormalMap, uv).rgb * 2.0 - 1.0;
    } else {
        uv = fragUV;
        albedo = texture(uAlbedoMap, uv).rgb;
        vec3 arm = texture(uMRAMap, uv).rgb;
        mra = vec3(arm.b, arm.g, arm.r);
        tn = texture(uNormalMap, uv).rgb * 2.0 - 1.0;
    }
    normal = perturb_normal(normal, fragPos, uv, normalize(tn));
    // Encode normal to [0,1] range for storage
    gNormal = vec4(normal * 0.5 + 0.5, 1.0);
    gAlbedo = vec4(albedo, 1.0);
    gMRA = vec4(mra, 1.0);
    gEmissive = vec4(0.0, 0.0, 0.0, 1.0);
}
