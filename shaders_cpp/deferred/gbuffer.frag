#version 330 core
// Deferred, geometry pass: three G-buffer outputs (MRT), derivative-based normal mapping.
uniform float u_material;   // 0 = cat, 1 = floor
uniform sampler2D cat_albedo;
uniform sampler2D cat_normal;
uniform sampler2D cat_arm;   // AO(r) / Roughness(g) / Metallic(b)
uniform sampler2D floor_albedo;
uniform sampler2D floor_normal;
uniform sampler2D floor_ao;
uniform sampler2D floor_roughness;
in vec3 gv_world_pos;
in vec3 gv_world_normal;
in vec2 gv_uv;
layout(location = 0) out vec4 g_albedo_out;
layout(location = 1) out vec4 g_normal_out;
layout(location = 2) out vec4 g_worldpos_out;

// Derivative-based TBN (Schueler 2010): a tangent frame from screen-space derivatives of
// world position + uv, no per-vertex tangent buffer.
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
    vec3 n = normalize(gv_world_normal);
    vec3 albedo = vec3(0.0, 0.0, 0.0);
    float spec_i = 0.0;
    float shininess = 32.0;
    vec3 perturbed = n;
    // sRGB albedo textures -> linear so the deferred lighting is done in linear space.
    vec3 sRGB = vec3(2.2, 2.2, 2.2);
    if (u_material > 0.5) {
        vec2 uv = vec2(gv_world_pos.x, gv_world_pos.z) * 0.35;
        float fb_ao = texture(floor_ao, uv).x;
        albedo = pow(texture(floor_albedo, uv).rgb, sRGB) * (0.5 + 0.5 * fb_ao);
        spec_i = (1.0 - texture(floor_roughness, uv).x) * 0.4;
        shininess = 24.0;
        // boost the tangent xy so the mortar reads, then renormalize
        vec3 tn_raw = texture(floor_normal, uv).rgb * 2.0 - vec3(1.0, 1.0, 1.0);
        vec3 tn = normalize(vec3(tn_raw.x * 3.0, tn_raw.y * 3.0, tn_raw.z));
        perturbed = perturb_normal(n, gv_world_pos, uv, tn);
    } else {
        vec3 alb = pow(texture(cat_albedo, gv_uv).rgb, sRGB);
        vec3 arm = texture(cat_arm, gv_uv).rgb;
        albedo = alb * (0.55 + 0.45 * arm.x);
        spec_i = (1.0 - arm.y) * 0.6;
        shininess = 48.0;
        vec3 tn = normalize(texture(cat_normal, gv_uv).rgb * 2.0 - vec3(1.0, 1.0, 1.0));
        perturbed = perturb_normal(n, gv_world_pos, gv_uv, tn);
    }
    g_albedo_out = vec4(albedo, spec_i);
    g_normal_out = vec4(perturbed, shininess);
    g_worldpos_out = vec4(gv_world_pos, u_material);
}
