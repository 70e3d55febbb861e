#version 330 core
// 11 - HDR + Bloom, post_vs: one screen-covering triangle; v_uv runs [0, 1] over the
// visible square. The bright, down, up and composite passes share it.
layout(location = 0) in vec2 q_pos;
out vec2 v_uv;

void main() {
    gl_Position = vec4(q_pos, 0.0, 1.0);
    v_uv = q_pos * 0.5 + vec2(0.5, 0.5);
}
