#version 330 core
// 08 - The Shadow Map, main pass: Blinn-Phong with a 3x3 PCF shadow lookup.
uniform vec3 u_light_dir;
uniform vec3 u_cam_pos;
uniform float u_is_floor;
uniform sampler2DShadow shadow_map;
in vec3 v_world_pos;
in vec3 v_world_normal;
in vec4 v_light_space;
layout(location = 0) out vec4 f_FragColor;

const float SHADOW_DIM_F = 1024.0;

// 3x3 PCF: average 9 taps over a one-texel radius; each tap is a hardware 2x2 compare.
float pcf_shadow(vec2 uv, float ref) {
    float texel = 1.0 / SHADOW_DIM_F;
    float sum = 0.0;
    for (int j = -1; j < 2; j++) {
        for (int i = -1; i < 2; i++) {
            vec2 off = vec2(i, j) * texel;
            sum += texture(shadow_map, vec3(uv + off, ref));
        }
    }
    return sum * (1.0 / 9.0);
}

void main() {
    vec3 n = normalize(v_world_normal);
    vec3 l = normalize(u_light_dir);
    float ndotl = max(dot(n, l), 0.0);
    vec3 v = normalize(u_cam_pos - v_world_pos);
    // Light-space NDC -> [0, 1] uv and depth reference.
    float w = max(v_light_space.w, 0.0001);
    vec3 ndc = v_light_space.xyz / vec3(w, w, w);
    vec2 shadow_uv = ndc.xy * 0.5 + vec2(0.5, 0.5);
    float ref_depth = ndc.z * 0.5 + 0.5;
    // N.L-scaled bias on top of the pipeline's polygon offset.
    float bias = max(0.0025 * (1.0 - ndotl), 0.0008);
    float lit = pcf_shadow(shadow_uv, ref_depth - bias);
    // Faces turned away from the light are in shadow regardless of the depth test.
    if (ndotl < 0.05) {
        lit = 0.0;
    }
    // Hemisphere ambient: warm-ish sky overhead blended to a dim ground bounce, by n.y.
    float amb_t = n.y * 0.5 + 0.5;
    vec3 ambient = mix(vec3(0.10, 0.09, 0.08), vec3(0.30, 0.34, 0.42), vec3(amb_t, amb_t, amb_t));
    vec3 sun = vec3(1.30, 1.15, 0.90);
    // Albedo: a checkerboard on the floor, a warm solid on the cube.
    vec3 albedo;
    float spec_strength = 0.5;
    if (u_is_floor > 0.5) {
        float gx = floor(v_world_pos.x * 0.5 + 100.0);
        float gz = floor(v_world_pos.z * 0.5 + 100.0);
        float cell = gx + gz;
        float parity = cell - floor(cell * 0.5) * 2.0;
        float checker = parity < 0.5 ? 0.85 : 0.30;
        albedo = vec3(checker, checker, checker) * vec3(0.80, 0.82, 0.88);
        spec_strength = 0.15;
    } else {
        albedo = vec3(0.85, 0.45, 0.30);
    }
    // Blinn-Phong specular, killed in shadow along with the diffuse.
    vec3 hvec = normalize(l + v);
    float spec = pow(max(dot(n, hvec), 0.0), 48.0) * lit * spec_strength;
    vec3 diffuse = sun * ndotl * lit;
    vec3 col = ambient * albedo + albedo * diffuse + vec3(spec, spec, spec);
    f_FragColor = vec4(col, 1.0);
}
