#version 330 core
// Deferred, lighting pass: shadowed sun (5x5 PCF), three point lights, hemisphere +
// equirectangular image-based lighting, SSAO; and the bottom filmstrip of the raw
// G-buffer (albedo / normal / world position) and SSAO.
uniform mat4 u_light_vp;
uniform vec3 u_cam_pos;
uniform vec3 u_light_dir;
uniform float u_time;
uniform sampler2D lit_albedo;
uniform sampler2D lit_normal;
uniform sampler2D lit_worldpos;
uniform sampler2D lit_ssao;
uniform sampler2DShadow shadow_map;
uniform sampler2D env_map;
in vec2 l_uv;
layout(location = 0) out vec4 frag_color;

const float SHADOW_DIM_F = 1024.0;

vec3 reflect3(vec3 i, vec3 nn) {
    return i - nn * (2.0 * dot(nn, i));
}

vec2 equirect_uv(vec3 d) {
    float u = atan(d.z, d.x) * 0.15915494 + 0.5;
    float v = acos(clamp(d.y, -1.0, 1.0)) * 0.31830989;
    return vec2(u, v);
}

float pcf_shadow(vec2 uv, float ref) {
    float texel = 1.0 / SHADOW_DIM_F;
    float sum = 0.0;
    for (int j = -2; j < 3; j++) {
        for (int i = -2; i < 3; i++) {
            vec2 off = vec2(float(i), float(j)) * texel;
            sum = sum + texture(shadow_map, vec3(uv + off, ref));
        }
    }
    return sum * (1.0 / 25.0);
}

vec3 point_light(vec3 lp, vec3 lcol, vec3 p, vec3 nrm, vec3 vdir, float shininess, float spec_i, float rng) {
    vec3 lvec = lp - p;
    float d = max(length(lvec), 0.0001);
    vec3 ldir = lvec / vec3(d, d, d);
    float ndotl = max(dot(nrm, ldir), 0.0);
    float atten = pow(max(1.0 - d / rng, 0.0), 2.0);
    vec3 hv = normalize(ldir + vdir);
    float spec = pow(max(dot(nrm, hv), 0.0), shininess) * spec_i;
    return lcol * (ndotl + spec) * atten;
}

void main() {
    // ----- bottom filmstrip: raw G-buffer (albedo / normal / world-pos) + SSAO -----
    float TH = 0.18;
    float GAP = 0.012;
    float Y0 = 0.02;
    bool in_strip = l_uv.y >= Y0 && l_uv.y <= Y0 + TH;
    float tv = (l_uv.y - Y0) / TH;
    float x0 = GAP;
    float x1 = GAP * 2.0 + TH;
    float x2 = GAP * 3.0 + TH * 2.0;
    float x3 = GAP * 4.0 + TH * 3.0;

    vec4 albedo_spec = texture(lit_albedo, l_uv);
    vec4 normal_sh = texture(lit_normal, l_uv);
    vec4 worldpos = texture(lit_worldpos, l_uv);
    float ssao_factor = texture(lit_ssao, l_uv).x;
    vec3 albedo = albedo_spec.rgb;
    float spec_i = albedo_spec.a;
    float shininess = normal_sh.a;
    vec3 p = worldpos.xyz;
    vec3 n_raw = normal_sh.xyz;
    bool is_bg = dot(n_raw, n_raw) < 0.01;
    vec3 n = vec3(0.0, 1.0, 0.0);
    if (!is_bg) {
        n = normalize(n_raw);
    }

    vec3 out_col = vec3(0.0, 0.0, 0.0);
    if (in_strip && l_uv.x >= x0 && l_uv.x <= x0 + TH) {
        out_col = texture(lit_albedo, vec2((l_uv.x - x0) / TH, tv)).rgb;
    } else if (in_strip && l_uv.x >= x1 && l_uv.x <= x1 + TH) {
        vec3 nn = texture(lit_normal, vec2((l_uv.x - x1) / TH, tv)).xyz;
        out_col = nn * 0.5 + vec3(0.5, 0.5, 0.5);
    } else if (in_strip && l_uv.x >= x2 && l_uv.x <= x2 + TH) {
        vec3 pp = texture(lit_worldpos, vec2((l_uv.x - x2) / TH, tv)).xyz;
        out_col = pp * 0.12 + vec3(0.5, 0.5, 0.5);
    } else if (in_strip && l_uv.x >= x3 && l_uv.x <= x3 + TH) {
        float ao = texture(lit_ssao, vec2((l_uv.x - x3) / TH, tv)).x;
        out_col = vec3(ao, ao, ao);
    } else if (is_bg) {
        float t = clamp(l_uv.y, 0.0, 1.0);
        out_col = mix(vec3(0.10, 0.10, 0.16), vec3(0.34, 0.24, 0.26), vec3(t, t, t));
    } else {
        vec3 view_dir = normalize(u_cam_pos - p);

        // shadowed sun: light-space NDC -> shadow uv + depth ref (GL z in [-1,1] -> [0,1])
        vec3 sun_dir = normalize(u_light_dir);
        float ndotl_sun = max(dot(n, sun_dir), 0.0);
        vec4 lc = u_light_vp * vec4(p, 1.0);
        float lw = max(lc.w, 0.0001);
        vec3 ndc = vec3(lc.x / lw, lc.y / lw, lc.z / lw);
        vec2 shadow_uv = vec2(ndc.x * 0.5 + 0.5, ndc.y * 0.5 + 0.5);
        float ref_depth = clamp(ndc.z * 0.5 + 0.5, 0.0, 1.0);
        float bias = max(0.0025 * (1.0 - ndotl_sun), 0.0009);
        float shadow = pcf_shadow(shadow_uv, ref_depth - bias);
        if (ndotl_sun < 0.05) {
            shadow = 0.0;
        }
        vec3 hv_sun = normalize(sun_dir + view_dir);
        float spec_sun = pow(max(dot(n, hv_sun), 0.0), shininess) * spec_i;
        vec3 sun = vec3(1.25, 1.10, 0.80) * (ndotl_sun + spec_sun) * shadow;

        // three orbiting coloured point lights, from u_time
        vec3 pts = vec3(0.0, 0.0, 0.0);
        for (int i = 0; i < 3; i++) {
            float fi = float(i);
            float ang = u_time * 0.7 + fi * 2.0944;
            vec3 lp = vec3(cos(ang) * 3.2, 1.6 + 0.6 * sin(u_time + fi), sin(ang) * 3.2);
            vec3 lcol = vec3(0.5 + 0.5 * cos(fi * 2.5), 0.5 + 0.5 * cos(fi * 2.5 + 2.0), 0.5 + 0.5 * cos(fi * 2.5 + 4.0));
            pts = pts + point_light(lp, lcol * 1.4, p, n, view_dir, shininess, spec_i, 5.5);
        }

        float ao = clamp(ssao_factor, 0.0, 1.0);
        float amb_t = n.y * 0.5 + 0.5;
        vec3 hemi = mix(vec3(0.08, 0.06, 0.05), vec3(0.22, 0.24, 0.36), vec3(amb_t, amb_t, amb_t));
        vec3 env_amb = texture(env_map, equirect_uv(n)).rgb;
        vec3 ambient = mix(hemi, env_amb, vec3(0.4, 0.4, 0.4));

        vec3 inc = vec3(-view_dir.x, -view_dir.y, -view_dir.z);
        vec3 rdir = reflect3(inc, n);
        vec3 env_refl = texture(env_map, equirect_uv(rdir)).rgb;
        float fres = pow(1.0 - max(dot(n, view_dir), 0.0), 4.0);
        vec3 env_spec = env_refl * (spec_i * (0.10 + 0.7 * fres));

        vec3 lighting = (ambient * ao) + (sun + pts) * (0.55 + 0.45 * ao) + env_spec * ao;
        // linear -> sRGB for the display (the default GL framebuffer does no sRGB encode)
        vec3 g = vec3(0.4545, 0.4545, 0.4545);
        out_col = pow(albedo * lighting, g);
    }
    frag_color = vec4(out_col, 1.0);
}
