#version 330 core
// 11 - HDR + Bloom, pass 2 (bright_fs): Frostbite soft-knee threshold times the Karis weight
// 1/(1+luma), from the HDR scene into bloom mip 0.
uniform sampler2D src0;             // the HDR scene (texture unit 0)
uniform float u_threshold;          // pixels below this luma are killed
uniform float u_soft_knee;          // soft-knee width around the threshold
in vec2 v_uv;
layout(location = 0) out vec4 f_FragColor;

void main() {
    vec3 hdr = texture(src0, v_uv).xyz;
    float luma = dot(hdr, vec3(0.2126, 0.7152, 0.0722));   // BT.709 luminance
    float knee = max(u_soft_knee, 0.0001);
    float tt = clamp((luma - u_threshold + knee) / (2.0 * knee), 0.0, 1.0);
    float curve = tt * tt * (3.0 - 2.0 * tt);
    float karis_weight = 1.0 / (1.0 + luma);
    f_FragColor = vec4(hdr * karis_weight * curve, 1.0);
}
