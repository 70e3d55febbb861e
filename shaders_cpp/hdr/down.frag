#version 330 core
// 11 - HDR + Bloom, pass 3 (down_fs): 5-tap Karis-bilinear downsample. The centre weighs
// 0.5, four diagonal taps at +-1 source texel 0.125 each.
uniform sampler2D src0;             // the larger mip (texture unit 0)
uniform vec2 u_src_rcp;             // 1 / source-mip size, the sample offset
in vec2 v_uv;
layout(location = 0) out vec4 f_FragColor;

void main() {
    vec2 o = u_src_rcp;
    vec3 c = texture(src0, v_uv).xyz;
    vec3 lt = texture(src0, v_uv + vec2(-o.x, -o.y)).xyz;
    vec3 rt = texture(src0, v_uv + vec2(o.x, -o.y)).xyz;
    vec3 lb = texture(src0, v_uv + vec2(-o.x, o.y)).xyz;
    vec3 rb = texture(src0, v_uv + vec2(o.x, o.y)).xyz;
    vec3 sum = c * 0.5 + (lt + rt + lb + rb) * 0.125;
    f_FragColor = vec4(sum, 1.0);
}
