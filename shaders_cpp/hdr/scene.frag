#version 330 core
// 11 - HDR + Bloom, pass 1 (seed 002, scene_fs): key light + ambient + rim into the RGBA16F
// target; emissive cubes are boosted 8x, well above 1.0.
uniform vec3 u_cam_pos;
in vec3 w_pos;
in vec3 w_normal;
in vec3 w_color;
in float w_emissive;
layout(location = 0) out vec4 f_FragColor;

const float EMISSIVE_BOOST = 8.0;   // glowing cubes hit ~8x -- well above the bright-pass knee
const float LIT_AMBIENT = 0.25;
const float LIT_KEY = 0.7;

void main() {
    vec3 n = normalize(w_normal);
    vec3 v = normalize(u_cam_pos - w_pos);
    vec3 l = normalize(vec3(0.5, 1.0, 0.3));
    float key = max(dot(n, l), 0.0) * LIT_KEY + LIT_AMBIENT;
    float rim = pow(1.0 - max(dot(n, v), 0.0), 2.5);
    // lit_lo stays in [0, 1]; emissive cubes multiply by EMISSIVE_BOOST, so the float
    // target carries values up to ~8 that the bright pass will threshold.
    vec3 lit_lo = w_color * key + vec3(0.25, 0.35, 0.55) * rim * 0.4;
    vec3 lit = lit_lo * (1.0 + w_emissive * (EMISSIVE_BOOST - 1.0));
    f_FragColor = vec4(lit, 1.0);
}
