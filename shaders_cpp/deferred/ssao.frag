#version 330 core
// Deferred, SSAO pass: 16 samples in a normal-oriented hemisphere, range-checked.
uniform mat4 u_view;
uniform mat4 u_proj;
uniform sampler2D ssao_g_normal;
uniform sampler2D ssao_g_worldpos;
in vec2 l_uv;
layout(location = 0) out vec4 ssao_out;

const int SSAO_K = 16;
const float SSAO_RADIUS = 0.6;
const float SSAO_BIAS = 0.03;
const float SSAO_STRENGTH = 1.7;

float smoothstep3(float a, float b, float x) {
    float t = clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

float hash21(vec2 p) {
    float v = sin(dot(p, vec2(127.1, 311.7))) * 43758.5453;
    return v - floor(v);
}

void main() {
    vec3 n_raw = texture(ssao_g_normal, l_uv).xyz;
    float ao = 1.0;
    if (dot(n_raw, n_raw) >= 0.01) {
        vec3 n = normalize(n_raw);
        vec3 p = texture(ssao_g_worldpos, l_uv).xyz;
        float cur_vz = (u_view * vec4(p, 1.0)).z;

        vec3 up = vec3(0.0, 1.0, 0.0);
        if (abs(n.y) > 0.95) {
            up = vec3(1.0, 0.0, 0.0);
        }
        vec3 tangent = normalize(cross(up, n));
        vec3 bitangent = cross(n, tangent);
        float ang0 = hash21(l_uv * 1024.0) * 6.2831853;

        float occ = 0.0;
        for (int i = 0; i < SSAO_K; i++) {
            float fi = (float(i) + 0.5) / float(SSAO_K);
            float ang = ang0 + float(i) * 2.3998277;
            float rr = SSAO_RADIUS * sqrt(fi);
            vec3 off = (cos(ang) * tangent + sin(ang) * bitangent) * rr + n * (rr * 0.5);
            vec3 sp = p + off;
            vec4 clip = u_proj * u_view * vec4(sp, 1.0);
            float wv = max(clip.w, 0.0001);
            vec2 suv = vec2(clip.x / wv * 0.5 + 0.5, clip.y / wv * 0.5 + 0.5);
            vec3 stored_p = texture(ssao_g_worldpos, suv).xyz;
            vec3 stored_n = texture(ssao_g_normal, suv).xyz;
            float stored_vz = (u_view * vec4(stored_p, 1.0)).z;
            float sample_vz = (u_view * vec4(sp, 1.0)).z;
            float range_check = smoothstep3(0.0, 1.0, SSAO_RADIUS / max(abs(cur_vz - stored_vz), 0.0001));
            // view looks down -Z: a stored surface closer to the camera (greater z) occludes
            if (clip.w > 0.0 && suv.x >= 0.0 && suv.x <= 1.0 && suv.y >= 0.0 && suv.y <= 1.0
                    && dot(stored_n, stored_n) > 0.01 && stored_vz >= sample_vz + SSAO_BIAS) {
                occ = occ + range_check;
            }
        }
        ao = clamp(1.0 - SSAO_STRENGTH * occ / float(SSAO_K), 0.0, 1.0);
    }
    ssao_out = vec4(ao, ao, ao, 1.0);
}
