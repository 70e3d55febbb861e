#version 330 core
// 11 - HDR + Bloom, pass 4 (up_fs): 9-tap tent (1-2-1 / 2-4-2 / 1-2-1, sum 16) of the
// smaller mip; the host blends it ONE/ONE onto the larger one.
uniform sampler2D src0;             // the smaller mip (texture unit 0)
uniform vec2 u_src_rcp;             // 1 / source-mip size, the sample offset
in vec2 v_uv;
layout(location = 0) out vec4 f_FragColor;

void main() {
    vec2 o = u_src_rcp;
    vec3 s00 = texture(src0, v_uv + vec2(-o.x, -o.y)).xyz;
    vec3 s10 = texture(src0, v_uv + vec2(0.0, -o.y)).xyz;
    vec3 s20 = texture(src0, v_uv + vec2(o.x, -o.y)).xyz;
    vec3 s01 = texture(src0, v_uv + vec2(-o.x, 0.0)).xyz;
    vec3 s11 = texture(src0, v_uv).xyz;
    vec3 s21 = texture(src0, v_uv + vec2(o.x, 0.0)).xyz;
    vec3 s02 = texture(src0, v_uv + vec2(-o.x, o.y)).xyz;
    vec3 s12 = texture(src0, v_uv + vec2(0.0, o.y)).xyz;
    vec3 s22 = texture(src0, v_uv + vec2(o.x, o.y)).xyz;
    vec3 tent = ((s00 + s20 + s02 + s22) * (1.0 / 16.0) +
        (s10 + s01 + s21 + s12) * (2.0 / 16.0) +
        s11 * (4.0 / 16.0));
    f_FragColor = vec4(tent, 1.0);
}
