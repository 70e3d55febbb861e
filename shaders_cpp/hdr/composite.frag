#version 330 core
// 11 - HDR + Bloom, pass 5 (composite_fs): HDR scene + bloom, ACES filmic fit, gamma 1/2.2,
// to the default framebuffer.
uniform sampler2D src0;             // the HDR scene (texture unit 0)
uniform sampler2D src_bloom;        // bloom mip 0 (texture unit 1)
uniform float u_bloom_intensity;    // how loud bloom is over the scene
in vec2 v_uv;
layout(location = 0) out vec4 f_FragColor;

// ACES filmic fit (Narkowicz 2015): one rational polynomial that mimics the ACES
// shoulder/toe, mapping the unbounded HDR range into [0, 1].
vec3 aces_fit(vec3 x) {
    vec3 a = vec3(2.51, 2.51, 2.51);
    vec3 b = vec3(0.03, 0.03, 0.03);
    vec3 c = vec3(2.43, 2.43, 2.43);
    vec3 d = vec3(0.59, 0.59, 0.59);
    vec3 e = vec3(0.14, 0.14, 0.14);
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), vec3(0.0, 0.0, 0.0), vec3(1.0, 1.0, 1.0));
}

void main() {
    vec3 hdr = texture(src0, v_uv).xyz;
    vec3 bloom = texture(src_bloom, v_uv).xyz;
    vec3 merged = hdr + bloom * u_bloom_intensity;
    vec3 mapped = aces_fit(merged);
    // WebGL2's default framebuffer does no sRGB encode, so gamma-encode here.
    float g = 1.0 / 2.2;
    vec3 encoded = pow(mapped, vec3(g, g, g));
    f_FragColor = vec4(encoded, 1.0);
}
